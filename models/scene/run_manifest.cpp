#include "models/scene/run_manifest.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "assembly/atomic_file.hpp"
#include "assembly/content_hash.hpp"
#include "assembly/error.hpp"
#include "assembly/version.hpp"
#include "models/output/result_series.hpp"

namespace pc {
namespace {

namespace fs = std::filesystem;

const char* const manifest_name = "manifest.json";
const char* const lock_name = ".piezocontact.lock";

std::string now_utc() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

std::string file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// What the run writes: in each foundation folder its tables, summary, checkpoint and VTU series (and a
// .tmp of an atomic write cut short); at the top, the sweep's table.
bool is_output_name(const std::string& name, const std::string& scene_name, bool top_level) {
  if (top_level) return name == "sweep_phi_f.csv" || name == "sweep_phi_f.csv.tmp";
  for (const char* table : {"summary.json", "history.csv", "gamma_c.csv", "grid.csv", "final_nodes.csv",
                            "final_cells.csv", "checkpoint.bin"})
    if (name == table) return true;
  return name.ends_with(".tmp") || name == scene_name + ".pvd" || ResultSeries::is_step_file(scene_name, name);
}

// The run's folders: the top and one per foundation; each regular file in them with its path relative
// to the top (manifest and lock excluded).
std::vector<std::pair<std::string, bool>> files_in(const std::string& directory, const Scene& scene) {
  std::vector<std::pair<std::string, bool>> out;  // (relative path, at the top level)
  std::error_code error;
  auto scan = [&](const fs::path& folder, const std::string& prefix, bool top) {
    for (const auto& entry : fs::directory_iterator(folder, error)) {
      const std::string name = entry.path().filename().string();
      if (!entry.is_regular_file(error) || (top && (name == manifest_name || name == lock_name))) continue;
      if (top && name.starts_with(".piezocontact.write_test.")) continue;
      out.emplace_back(prefix + name, top);
    }
  };
  scan(directory, "", true);
  for (const SceneFoundation& f : scene.foundations)
    if (fs::is_directory(fs::path(directory) / f.name, error)) scan(fs::path(directory) / f.name, f.name + "/", false);
  std::sort(out.begin(), out.end());
  return out;
}

// A path a manifest lists, checked to stay inside the folder (a hand-edited manifest cannot remove
// anything outside it).
bool is_inside(const std::string& relative) {
  const fs::path p(relative);
  if (p.empty() || p.is_absolute()) return false;
  for (const auto& part : p)
    if (part == "..") return false;
  return true;
}

}  // namespace

std::string scene_fingerprint(const Scene& scene) {
  // Budgets and the rhythm of progress lines and checkpoints do not change a result: a stopped run may be
  // resumed with a longer wall-time limit.
  Json json = scene.json;
  const std::map<std::string, std::vector<std::string>> ignored = {{"time", {"max_wall_seconds", "max_attempts"}},
                                                                   {"output", {"progress_every", "checkpoint_every"}}};
  for (const auto& [section, keys] : ignored) {
    const auto found = json.is_object() ? json.find(section) : std::nullopt;
    if (!found || !found->is_object()) continue;
    Json kept = Json::object();
    for (const auto& [key, value] : found->members())
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) kept.set(key, value);
    json.set(section, kept);
  }
  std::uint64_t hash = content_hash(json.dump(0));
  if (const auto mesh = scene.json.find("mesh"); mesh && mesh->is_object())
    if (const auto gmsh = mesh->find("gmsh"); gmsh && gmsh->is_string()) {
      fs::path path = gmsh->as_string();
      if (path.is_relative()) path = fs::path(scene.directory) / path;
      hash = content_hash(file_bytes(path), hash);
    }
  if (const auto plugins = scene.json.find("plugins"); plugins && plugins->is_array())
    for (const Json& item : plugins->as_array()) {
      fs::path path = item.as_string();
      if (path.is_relative()) path = fs::path(scene.directory) / path;
      hash = content_hash(file_bytes(path), hash);
    }
  char text[20];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

RunManifest::RunManifest(std::string directory, const Scene& scene)
    : directory_(std::move(directory)), scene_(&scene), fingerprint_(scene_fingerprint(scene)), started_(now_utc()) {
  for (const SceneFoundation& f : scene.foundations) parts_[f.name] = {"pending", ""};
}

RunManifest RunManifest::start(const std::string& directory, const Scene& scene) {
  RunManifest m(directory, scene);
  const fs::path top(directory);
  std::error_code error;
  // The files an earlier run's manifest says are its own ...
  if (fs::exists(top / manifest_name, error)) {
    try {
      const Json old = read_json_file((top / manifest_name).string());
      if (const auto files = old.find("files"); files && files->is_array())
        for (const Json& f : files->as_array())
          if (f.is_string() && is_inside(f.as_string()) && fs::remove(top / f.as_string(), error))
            m.removed_.push_back(f.as_string());
    } catch (const Error&) {
      // An unreadable manifest lists nothing: the names below still clear the run's own outputs.
    }
  }
  // ... and whatever carries the name of one of this run's outputs, in its own folders.
  for (const auto& [relative, top_level] : files_in(directory, scene)) {
    if (is_output_name(fs::path(relative).filename().string(), scene.name, top_level)) {
      if (fs::remove(top / relative, error)) m.removed_.push_back(relative);
    } else {
      m.foreign_.push_back(relative);
    }
  }
  m.save();
  return m;
}

RunManifest RunManifest::resume(const std::string& directory, const Scene& scene) {
  const fs::path path = fs::path(directory) / manifest_name;
  require(fs::exists(path), "--resume: '", directory, "' has no ", manifest_name,
          ": there is no run to resume there (run without --resume to start one)");
  const Json old = read_json_file(path.string());
  RunManifest m(directory, scene);
  const std::string fingerprint = old.at("scene").at("fingerprint").as_string();
  if (fingerprint != m.fingerprint_) {
    std::string overrides;
    if (const auto o = old.at("scene").find("overrides"))
      for (const Json& item : o->as_array()) overrides += " --set " + item.as_string();
    fail("--resume: the run in '", directory, "' is of another scene (fingerprint ", fingerprint, ", this one is ",
         m.fingerprint_, "): it was run as '", old.at("scene").at("file").as_string(), "'",
         overrides.empty() ? " without --set" : overrides,
         "; resume with the same scene file, mesh and overrides, or run without --resume to start anew");
  }
  m.started_ = old.at("started").as_string();
  m.resumes_ = old.at("resumes").as_int() + 1;
  for (const auto& [name, part] : old.at("parts").members())
    m.parts_[name] = {part.at("state").as_string(), part.find("message") ? part.at("message").as_string() : ""};
  for (const Json& f : old.at("not_of_this_run").as_array()) m.foreign_.push_back(f.as_string());
  m.save();
  return m;
}

std::string RunManifest::part_state(const std::string& part) const {
  const auto it = parts_.find(part);
  return it == parts_.end() ? "pending" : it->second.first;
}

void RunManifest::set_part(const std::string& part, const std::string& state, const std::string& message) {
  parts_[part] = {state, message};
  save();
}

void RunManifest::finish(bool completed, const std::string& reason) {
  state_ = completed ? "completed" : "stopped";
  reason_ = reason;
  save();
}

std::vector<std::string> RunManifest::list_run_files() const {
  std::vector<std::string> files;
  for (const auto& [relative, top_level] : files_in(directory_, *scene_))
    if (std::find(foreign_.begin(), foreign_.end(), relative) == foreign_.end() && !relative.ends_with(".tmp"))
      files.push_back(relative);
  return files;
}

void RunManifest::save() {
  Json overrides = Json::array();
  for (const std::string& o : scene_->overrides) overrides.push_back(Json(o));
  Json parts = Json::object();
  for (const auto& [name, part] : parts_) {
    Json p = Json::object({{"state", Json(part.first)}});
    if (!part.second.empty()) p.set("message", Json(part.second));
    parts.set(name, p);
  }
  Json files = Json::array(), foreign = Json::array();
  for (const std::string& f : list_run_files()) files.push_back(Json(f));
  for (const std::string& f : foreign_) foreign.push_back(Json(f));
  Json m = Json::object({
      {"format", Json(1)},
      {"program", Json(std::string("piezocontact ") + library_version())},
      {"compiler", Json(std::string(__VERSION__))},
      {"scene",
       Json::object({{"name", Json(scene_->name)},
                     {"file", Json(scene_->file.empty() ? std::string() : fs::absolute(scene_->file).string())},
                     {"overrides", overrides},
                     {"fingerprint", Json(fingerprint_)}})},
      {"state", Json(state_)},
      {"started", Json(started_)},
      {"updated", Json(now_utc())},
      {"pid", Json(::getpid())},
      {"resumes", Json(resumes_)},
      {"parts", parts},
      {"files", files},
      {"not_of_this_run", foreign},
  });
  if (!reason_.empty()) m.set("reason", Json(reason_));
  write_atomically((fs::path(directory_) / manifest_name).string(), "manifest",
                   [&](std::ostream& out) { out << m.dump(2) << "\n"; });
}

}  // namespace pc
