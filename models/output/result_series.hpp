#pragma once
// A time series of VTU files and the PVD collection that ParaView opens as one animated data set. The
// collection is rewritten after every step, so a run that is interrupted (or still running) leaves a
// readable series of every step finished so far, each at its real time. A distributed run writes each
// step in pieces, one per process, gathered by a .pvtu file.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "assembly/vtu_writer.hpp"

namespace pc {

class ResultSeries {
 public:
  // Creates the directory (and its parents) now, so that a bad path fails before the run starts. The
  // files are <directory>/<basename>_<step, 6 digits>.vtu, in the given format, and <directory>/<basename>.pvd.
  ResultSeries(const std::string& directory, std::string basename, VtuFormat format = kDefaultVtuFormat);

  // Writes the step's VTU file, then the collection of every step written so far. Writing a step again
  // (e.g. after a retried step) replaces its file and its time. Returns the path of the VTU file.
  std::string write(int step, double time, const VtuWriter& writer);

  // A distributed run (assembly/processes.hpp): from now on each process writes the piece of its cells
  // (one flag per mesh cell) as <basename>_<step>_<rank>.vtu, and the writer process the step's
  // <basename>_<step>.pvtu naming the pieces, which the collection lists. Every process calls write().
  void write_pieces(std::vector<char> owned_cells);

  std::string pvd_path() const;
  // Whether a file name is one of a series' files: <basename>_<digits>.vtu, a step's .pvtu, or a piece
  // <basename>_<digits>_<digits>.vtu.
  static bool is_step_file(const std::string& basename, const std::string& file_name);

  // The steps written so far, with their times (what a checkpoint keeps of the series).
  std::vector<std::pair<int, double>> written() const;
  // Continues the series of a resumed run: these steps (a checkpoint's written()) are taken as written;
  // every other <basename>_*.vtu in the directory (computed after the checkpoint, or foreign) is removed,
  // and the collection is rewritten.
  void continue_from(const std::vector<std::pair<int, double>>& steps);

 private:
  std::string directory_;
  std::string basename_;
  VtuFormat format_;
  std::map<int, std::pair<double, std::string>> steps_;  // step -> (time, file name relative to the .pvd)
  std::vector<char> piece_cells_;                        // distributed: this process's cells

  std::string file_name(int step) const;  // the step's .vtu, or its .pvtu when written in pieces
  std::string piece_name(int step, int rank) const;
  void write_collection() const;
};

}  // namespace pc
