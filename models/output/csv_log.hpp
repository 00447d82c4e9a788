#pragma once
// Comma-separated tables of numbers: CsvLog appends one row per step and flushes it, so that a run that
// stops early keeps every row computed, and a row that cannot be written whole (a full disk) is cut off
// again, so that the file only ever holds complete rows; write_csv writes a whole table at once, atomically. Values are
// written with 17 significant digits, so they read back as the same doubles (NaN and infinities as
// "nan", "inf", "-inf", which numpy and pandas read).
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace pc {

class CsvLog {
 public:
  // Truncates the file and writes the header. Column names may not contain commas, quotes or line breaks.
  CsvLog(std::string path, std::vector<std::string> columns);
  // Continues the log of a resumed run: the file must have this header and at least `rows_kept` rows; the
  // rows after them (computed after the checkpoint the run resumes from) are cut off.
  static CsvLog continue_after(std::string path, std::vector<std::string> columns, int rows_kept);

  // Appends one row (one value per column) and flushes it to the file.
  void row(const std::vector<double>& values);

  const std::string& path() const { return path_; }
  int rows_written() const { return rows_written_; }

 private:
  std::string path_;
  std::vector<std::string> columns_;
  std::ofstream out_;
  int rows_written_ = 0;
  std::uintmax_t complete_bytes_ = 0;  // the file's size after its last complete row

  struct Continued {};
  CsvLog(std::string path, std::vector<std::string> columns, Continued);
};

// Writes a whole table (one vector per row) to path + ".tmp" and renames it over path, so that a reader
// never sees a half-written table.
void write_csv(const std::string& path, const std::vector<std::string>& columns,
               const std::vector<std::vector<double>>& rows);

}  // namespace pc
