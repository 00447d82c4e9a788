#pragma once
// OUT/manifest.json: what a run into OUT is and where it stands, so that a folder of results cannot lie.
// It records the scene (file, --set overrides and a fingerprint of the scene, its mesh file and plugins),
// the build, the run's state ("running", "completed" or "stopped" with the reason) and each part's
// (one per foundation, and the phi_f sweep), and which files belong to the run. It is rewritten
// atomically at every change of state and every checkpoint. A run killed outright leaves "running": the
// lock (OutputDirectoryLock) then tells that no process holds the folder.
//
// A new run into a folder first removes what an earlier run left there: the files its manifest lists,
// and any file with the name of one of this run's outputs in the run's foundation folders (an earlier run
// of another mesh or without a manifest); any other file it finds is listed under "not_of_this_run" and
// reported, never mixed in. A resumed run (--resume) keeps the folder and requires the same scene.
#include <map>
#include <string>
#include <vector>

#include "models/scene/scene.hpp"

namespace pc {

// The scene as run: its JSON after overrides (budgets and the progress and checkpoint rhythm left out),
// its gmsh file and plugin files, as a 16-digit hex number.
std::string scene_fingerprint(const Scene& scene);

class RunManifest {
 public:
  // A new run: cleans the folder as above and writes the manifest ("running").
  static RunManifest start(const std::string& directory, const Scene& scene);
  // A resumed run: reads the manifest, which must exist and be of this scene; throws a pc::Error saying
  // why not (no manifest, another scene: the overrides it was run with are named).
  static RunManifest resume(const std::string& directory, const Scene& scene);

  const std::string& directory() const { return directory_; }
  // The state of a part ("insulated", "sweep_phi_f"): "pending" until it starts, then "running",
  // "completed" or "stopped".
  std::string part_state(const std::string& part) const;
  void set_part(const std::string& part, const std::string& state, const std::string& message = "");
  // The whole run's end: "completed", or "stopped" with the reason. Saves.
  void finish(bool completed, const std::string& reason);
  // Lists the run's files and writes the manifest atomically.
  void save();

  const std::vector<std::string>& removed() const { return removed_; }
  const std::vector<std::string>& not_of_this_run() const { return foreign_; }

 private:
  RunManifest(std::string directory, const Scene& scene);
  std::vector<std::string> list_run_files() const;

  std::string directory_;
  const Scene* scene_;
  std::string fingerprint_, state_ = "running", reason_, started_;
  int resumes_ = 0;
  std::map<std::string, std::pair<std::string, std::string>> parts_;  // part -> (state, message)
  std::vector<std::string> removed_, foreign_;
};

}  // namespace pc
