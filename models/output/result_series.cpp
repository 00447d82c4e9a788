#include "models/output/result_series.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <vector>

#include "assembly/error.hpp"
#include "assembly/processes.hpp"

namespace pc {

ResultSeries::ResultSeries(const std::string& directory, std::string basename, VtuFormat format)
    : directory_(directory.empty() ? "." : directory), basename_(std::move(basename)), format_(format) {
  require(!basename_.empty(), "ResultSeries: empty basename for the files in '", directory_, "'");
  std::error_code error;
  std::filesystem::create_directories(directory_, error);
  require(!error, "ResultSeries: cannot create the output directory '", directory_, "': ", error.message());
}

std::string ResultSeries::pvd_path() const {
  return (std::filesystem::path(directory_) / (basename_ + ".pvd")).string();
}

std::string ResultSeries::file_name(int step) const {
  char number[16];
  std::snprintf(number, sizeof number, "%06d", step);
  return basename_ + "_" + number + (piece_cells_.empty() ? ".vtu" : ".pvtu");
}

std::string ResultSeries::piece_name(int step, int rank) const {
  char number[32];
  std::snprintf(number, sizeof number, "%06d_%d", step, rank);
  return basename_ + "_" + number + ".vtu";
}

void ResultSeries::write_pieces(std::vector<char> owned_cells) {
  if (processes::distributed()) piece_cells_ = std::move(owned_cells);
}

void ResultSeries::write_collection() const {
  std::vector<std::pair<double, std::string>> collection;
  for (const auto& [s, entry] : steps_) collection.push_back(entry);
  write_pvd(pvd_path(), collection);
}

std::string ResultSeries::write(int step, double time, const VtuWriter& writer) {
  require(step >= 0, "ResultSeries '", pvd_path(), "': step must be >= 0, got ", step);
  require(std::isfinite(time), "ResultSeries '", pvd_path(), "': time of step ", step, " is not finite: ", time);
  const std::string file = file_name(step);
  const std::string path = (std::filesystem::path(directory_) / file).string();
  if (piece_cells_.empty()) {
    writer.write(path, format_);
  } else {
    writer.write((std::filesystem::path(directory_) / piece_name(step, processes::rank())).string(), format_,
                 piece_cells_);
    // The .pvtu names the pieces once they are all written (a failed piece stops every process).
    if (processes::any(false)) return path;
    if (processes::is_writer()) {
      std::vector<std::string> pieces;
      for (int rank = 0; rank < processes::count(); ++rank) pieces.push_back(piece_name(step, rank));
      writer.write_pvtu(path, pieces);
    }
  }
  steps_[step] = {time, file};
  if (processes::is_writer()) write_collection();
  return path;
}

namespace {

// The step of a series file name (<basename>_<digits>.vtu, .pvtu, or _<digits>_<digits>.vtu), or -1.
int step_of(const std::string& basename, const std::string& file_name) {
  const std::string prefix = basename + "_";
  if (!file_name.starts_with(prefix)) return -1;
  const std::string rest = file_name.substr(prefix.size());
  size_t step_end = 0;
  while (step_end < rest.size() && std::isdigit(static_cast<unsigned char>(rest[step_end]))) ++step_end;
  if (step_end == 0) return -1;
  // A step past int's range is no step a run writes (its file is cleared as foreign).
  const int step = step_end > 9 ? std::numeric_limits<int>::max() : std::stoi(rest.substr(0, step_end));
  const std::string tail = rest.substr(step_end);
  if (tail == ".vtu" || tail == ".pvtu") return step;
  // A piece: _<rank digits>.vtu
  if (tail.size() > 5 && tail[0] == '_' && tail.ends_with(".vtu")) {
    const std::string rank = tail.substr(1, tail.size() - 5);
    if (!rank.empty() && std::all_of(rank.begin(), rank.end(), [](unsigned char c) { return std::isdigit(c); }))
      return step;
  }
  return -1;
}

}  // namespace

bool ResultSeries::is_step_file(const std::string& basename, const std::string& file_name) {
  return step_of(basename, file_name) >= 0;
}

std::vector<std::pair<int, double>> ResultSeries::written() const {
  std::vector<std::pair<int, double>> out;
  for (const auto& [step, entry] : steps_) out.emplace_back(step, entry.first);
  return out;
}

void ResultSeries::continue_from(const std::vector<std::pair<int, double>>& steps) {
  steps_.clear();
  // A kept step's file is the one the earlier part of the run wrote: a .vtu, or a .pvtu of pieces (a
  // run may be resumed on another number of processes).
  const auto exists = [&](const std::string& name) {
    return std::filesystem::is_regular_file(std::filesystem::path(directory_) / name);
  };
  for (const auto& [step, time] : steps) {
    std::string file = file_name(step);
    const std::string other =
        file.ends_with(".pvtu") ? file.substr(0, file.size() - 5) + ".vtu" : file.substr(0, file.size() - 4) + ".pvtu";
    if (!exists(file) && exists(other)) file = other;
    require(exists(file), "ResultSeries '", pvd_path(), "': cannot continue: the file of step ", step, " (", file,
            ") is missing");
    steps_[step] = {time, file};
  }
  // The writer alone clears the files of other steps (those computed after the checkpoint, or foreign).
  if (!processes::is_writer()) return;
  for (const auto& entry : std::filesystem::directory_iterator(directory_)) {
    const std::string name = entry.path().filename().string();
    const int step = step_of(basename_, name);
    if (step < 0) continue;
    const auto kept = steps_.find(step);
    const std::string& file = kept == steps_.end() ? name : kept->second.second;
    const bool piece_of_kept = file.ends_with(".pvtu") && name.starts_with(file.substr(0, file.size() - 5) + "_");
    if (kept == steps_.end() || (name != kept->second.second && !piece_of_kept)) std::filesystem::remove(entry.path());
  }
  write_collection();
}

}  // namespace pc
