#include "models/output/csv_log.hpp"

#include <charconv>
#include <filesystem>
#include <sstream>

#include "assembly/atomic_file.hpp"
#include "assembly/error.hpp"

namespace pc {
namespace {

// Checked before any file is opened, so that a bad call leaves existing files untouched.
void check_columns(const std::string& path, const std::vector<std::string>& columns) {
  require(!columns.empty(), "CSV '", path, "': no columns");
  // Quoting is not supported: names stay plain so that every CSV reader splits them the same way.
  for (const std::string& name : columns)
    require(!name.empty() && name.find_first_of(",\"\r\n") == std::string::npos, "CSV '", path, "': column name '",
            name, "' is empty or contains a comma, quote or line break");
}

void check_row(const std::string& path, size_t num_columns, const std::vector<double>& values) {
  require(values.size() == num_columns, "CSV '", path, "': a row has ", values.size(), " values for ", num_columns,
          " columns");
}

void write_header(std::ostream& out, const std::vector<std::string>& columns) {
  for (size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << columns[i];
  out << '\n';
}

// Each value in the shortest text that reads back as the same double (std::to_chars), several times
// faster than printf's "%.17g", which the final tables (a row per node and per cell) spent most of their
// time in, and shorter.
void write_row(std::ostream& out, const std::vector<double>& values) {
  char text[32 * 64];
  size_t used = 0;
  for (size_t i = 0; i < values.size(); ++i) {
    if (used + 32 > sizeof text) {
      out.write(text, std::streamsize(used));
      used = 0;
    }
    if (i) text[used++] = ',';
    used = size_t(std::to_chars(text + used, text + sizeof text, values[i]).ptr - text);
  }
  text[used++] = '\n';
  out.write(text, std::streamsize(used));
}

}  // namespace

CsvLog::CsvLog(std::string path, std::vector<std::string> columns)
    : path_(std::move(path)), columns_(std::move(columns)) {
  check_columns(path_, columns_);
  out_.open(path_, std::ios::trunc);
  require(bool(out_), "CsvLog: cannot open '", path_, "' for writing (does its directory exist?)");
  write_header(out_, columns_);
  out_.flush();
  require(bool(out_), "CsvLog: writing the header of '", path_, "' failed (disk full?)");
  complete_bytes_ = std::filesystem::file_size(path_);
}

CsvLog::CsvLog(std::string path, std::vector<std::string> columns, Continued)
    : path_(std::move(path)), columns_(std::move(columns)) {}

CsvLog CsvLog::continue_after(std::string path, std::vector<std::string> columns, int rows_kept) {
  check_columns(path, columns);
  std::ifstream in(path, std::ios::binary);
  require(bool(in), "CsvLog: cannot continue '", path, "': it cannot be read");
  std::ostringstream header;
  write_header(header, columns);
  std::string line;
  std::uintmax_t bytes = 0;
  int rows = -1;  // the header is row -1
  while (rows < rows_kept && std::getline(in, line) && !in.eof()) {
    if (rows == -1)
      require(line + "\n" == header.str(), "CsvLog: cannot continue '", path, "': its header is '", line,
              "', expected '", header.str().substr(0, header.str().size() - 1), "'");
    bytes += line.size() + 1;
    ++rows;
  }
  require(rows == rows_kept, "CsvLog: cannot continue '", path, "' after row ", rows_kept, ": it has only ",
          std::max(rows, 0), " complete rows");
  in.close();
  std::filesystem::resize_file(path, bytes);
  CsvLog log(std::move(path), std::move(columns), Continued{});
  log.out_.open(log.path_, std::ios::app);
  require(bool(log.out_), "CsvLog: cannot open '", log.path_, "' to continue it");
  log.rows_written_ = rows_kept;
  log.complete_bytes_ = bytes;
  return log;
}

void CsvLog::row(const std::vector<double>& values) {
  check_row(path_, columns_.size(), values);
  std::ostringstream text;
  write_row(text, values);
  out_ << text.str();
  out_.flush();
  if (!out_) {
    // Part of the row may have reached the file: cut it off, so that the file ends with a whole row.
    out_.close();
    std::error_code ignored;
    std::filesystem::resize_file(path_, complete_bytes_, ignored);
    fail("CsvLog: writing row ", rows_written_ + 1, " of '", path_, "' failed (disk full?); the file keeps its ",
         rows_written_, " complete rows");
  }
  complete_bytes_ += text.str().size();
  ++rows_written_;
}

void write_csv(const std::string& path, const std::vector<std::string>& columns,
               const std::vector<std::vector<double>>& rows) {
  check_columns(path, columns);
  for (const std::vector<double>& row : rows) check_row(path, columns.size(), row);

  write_atomically(path, "write_csv", [&](std::ostream& out) {
    write_header(out, columns);
    for (const std::vector<double>& row : rows) write_row(out, row);
  });
}

}  // namespace pc
