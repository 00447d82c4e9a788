#include "models/output/result_series.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "assembly/error.hpp"

namespace pc {

ResultSeries::ResultSeries(const std::string& directory, std::string basename)
    : directory_(directory.empty() ? "." : directory), basename_(std::move(basename)) {
  require(!basename_.empty(), "ResultSeries: empty basename for the files in '", directory_, "'");
  std::error_code error;
  std::filesystem::create_directories(directory_, error);
  require(!error, "ResultSeries: cannot create the output directory '", directory_, "': ", error.message());
}

std::string ResultSeries::pvd_path() const {
  return (std::filesystem::path(directory_) / (basename_ + ".pvd")).string();
}

std::string ResultSeries::write(int step, double time, const VtuWriter& writer) {
  require(step >= 0, "ResultSeries '", pvd_path(), "': step must be >= 0, got ", step);
  require(std::isfinite(time), "ResultSeries '", pvd_path(), "': time of step ", step, " is not finite: ", time);
  char number[16];
  std::snprintf(number, sizeof number, "%06d", step);
  const std::string file = basename_ + "_" + number + ".vtu";
  const std::string path = (std::filesystem::path(directory_) / file).string();
  writer.write(path);
  steps_[step] = {time, file};

  std::vector<std::pair<double, std::string>> collection;
  for (const auto& [s, entry] : steps_) collection.push_back(entry);
  write_pvd(pvd_path(), collection);
  return path;
}

}  // namespace pc
