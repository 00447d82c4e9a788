#include "models/output/result_series.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "assembly/error.hpp"

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
  return basename_ + "_" + number + ".vtu";
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
  writer.write(path, format_);
  steps_[step] = {time, file};
  write_collection();
  return path;
}

bool ResultSeries::is_step_file(const std::string& basename, const std::string& file_name) {
  const std::string prefix = basename + "_", suffix = ".vtu";
  if (file_name.size() <= prefix.size() + suffix.size() || !file_name.starts_with(prefix) ||
      !file_name.ends_with(suffix))
    return false;
  const std::string digits = file_name.substr(prefix.size(), file_name.size() - prefix.size() - suffix.size());
  return std::all_of(digits.begin(), digits.end(), [](unsigned char c) { return std::isdigit(c); });
}

std::vector<std::pair<int, double>> ResultSeries::written() const {
  std::vector<std::pair<int, double>> out;
  for (const auto& [step, entry] : steps_) out.emplace_back(step, entry.first);
  return out;
}

void ResultSeries::continue_from(const std::vector<std::pair<int, double>>& steps) {
  steps_.clear();
  for (const auto& [step, time] : steps) {
    const std::string file = file_name(step);
    require(std::filesystem::is_regular_file(std::filesystem::path(directory_) / file), "ResultSeries '", pvd_path(),
            "': cannot continue: the file of step ", step, " (", file, ") is missing");
    steps_[step] = {time, file};
  }
  for (const auto& entry : std::filesystem::directory_iterator(directory_)) {
    const std::string name = entry.path().filename().string();
    if (!is_step_file(basename_, name)) continue;
    const bool kept = std::any_of(steps_.begin(), steps_.end(), [&](const auto& s) { return s.second.second == name; });
    if (!kept) std::filesystem::remove(entry.path());
  }
  write_collection();
}

}  // namespace pc
