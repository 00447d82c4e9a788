// The command-line runner (installed as `piezocontact`):
//   piezocontact run SCENE [--out DIR] [--set key=value ...] [--only FOUNDATION] [--no-sweep] [--quiet] [--resume]
//                    [--target-error E] [--plugin LIB ...]
//   piezocontact check SCENE [--set key=value ...] [--plugin LIB ...]
//   piezocontact modes SCENE [--out DIR] [--set key=value ...] [--count N] [--shift HZ] [--open-circuit]
//                      [--plugin LIB ...]
//   piezocontact list [--plugin LIB ...]
//   piezocontact describe [NAME] [--markdown] [--plugin LIB ...]
// `run` validates the whole scene, then runs each foundation it lists and writes the results (see
// models/scene/scene_runner.hpp) as it goes. `check` validates and builds every foundation's model
// without running it, so it refuses whatever `run` would refuse before its first step. --set overrides
// any scene value by its dotted path: --set contact.c_nu=1e14 --set mesh.nx=120. `list` and `describe`
// print what a scene can name (laws, time schemes, solvers) with every parameter, from the registries;
// --plugin loads a plugin first, for every command (a scene loads those it names in "plugins", so a scene
// may name a law of a plugin it does not list when the command line loads it). --resume continues the run
// recorded in DIR/manifest.json (same scene and overrides) from its last checkpoint. `modes` writes the
// N (default 6) eigenfrequencies nearest to HZ (default 0: the lowest) and their shapes into
// DIR/<scene>/modes/ (models/scene/scene_modes.hpp); --open-circuit floats the driven electrodes (no
// charge) instead of shorting them, into DIR/<scene>/modes_open_circuit/. --target-error 1% (or 0.01)
// is the scene key target_error: pilot runs, then the order, mesh, scheme and steps whose estimated
// error is below it at the least predicted cost (models/scene/target_error.hpp).
// Exit status: 0 done, 1 a run stopped or an error, 2 a bad command line, 3 (`run --target-error`) every
// run completed but one's own estimate is above the target (models/scene/target_error_outcome.hpp).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <new>
#include <string>
#include <type_traits>
#include <vector>

#include "assembly/blas_info.hpp"
#include "assembly/error.hpp"
#include "assembly/processes.hpp"
#include "assembly/suggestions.hpp"
#include "assembly/version.hpp"
#include "models/output/duration_text.hpp"
#include "models/scene/interrupts.hpp"
#include "models/scene/plugins.hpp"
#include "models/scene/registry_catalog.hpp"
#include "models/scene/scene_modes.hpp"
#include "models/scene/scene_runner.hpp"
#include "models/scene/target_error_outcome.hpp"
#include "models/scene/time_estimate.hpp"

namespace {

// A number option's value; anything else ends the program with an error naming the option and the text.
template <class T> T number(const std::string& option, const std::string& text) {
  size_t used = 0;
  T value{};
  try {
    if constexpr (std::is_same_v<T, int>)
      value = std::stoi(text, &used);
    else
      value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size()) {
    std::fprintf(stderr, "error: %s must be a number, got '%s'\n", option.c_str(), text.c_str());
    std::exit(2);
  }
  return value;
}

int usage() {
  std::fprintf(
      stderr,
      "usage: piezocontact run SCENE [--out DIR] [--set key=value ...] [--only FOUNDATION] [--no-sweep] [--quiet] "
      "[--resume]\n"
      "                        [--target-error E (a fraction, 0.01, or a percentage, 1%%)] [--plugin LIB ...]\n"
      "       piezocontact check SCENE [--set key=value ...] [--plugin LIB ...]\n"
      "       piezocontact modes SCENE [--out DIR] [--set key=value ...] [--count N] [--shift HZ] [--open-circuit]\n"
      "                          [--plugin LIB ...]\n"
      "       piezocontact list [--plugin LIB ...]\n"
      "       piezocontact describe [NAME] [--markdown] [--plugin LIB ...]\n"
      "       piezocontact --version\n"
      "exit status: 0 done, 1 a run stopped or an error, 2 a bad command line, 3 a --target-error run missed its "
      "target\n");
  return 2;
}

// --target-error's value as the fraction the scene key holds: "1%" is 0.01, "0.01" is itself.
std::string target_error_fraction(const std::string& text) {
  const bool percent = !text.empty() && text.back() == '%';
  const double value = number<double>("--target-error", percent ? text.substr(0, text.size() - 1) : text);
  char fraction[32];
  std::snprintf(fraction, sizeof fraction, "%.17g", percent ? value / 100 : value);
  return fraction;
}

}  // namespace

// `list` and `describe`: what the registries hold.
int catalog(const std::string& command, int argc, char** argv) {
  std::string name;
  bool markdown = false;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--plugin" && i + 1 < argc)
      pc::load_plugin(argv[++i]);
    else if (arg == "--markdown" && command == "describe")
      markdown = true;
    else if (name.empty() && arg.rfind("--", 0) != 0 && command == "describe")
      name = arg;
    else
      return usage();
  }
  const auto sections = pc::registry_catalog();
  if (command == "list") {
    std::fputs(pc::catalog_list(sections).c_str(), stdout);
    return 0;
  }
  if (markdown) {
    if (!name.empty()) return usage();
    std::fputs(pc::catalog_markdown(sections).c_str(), stdout);
    return 0;
  }
  const std::string text = pc::catalog_describe(sections, name);
  if (text.empty()) {
    std::fprintf(stderr, "error: nothing registered is called '%s' (see: piezocontact list)\n", name.c_str());
    return 1;
  }
  std::fputs(text.c_str(), stdout);
  return 0;
}

// An error on one process of a distributed run ends them all (the others would wait for it for ever).
int failed() {
  if (pc::processes::distributed()) pc::processes::abort(1);
  return 1;
}

// glibc raises its mmap threshold to the size of each large block that is freed (up to 32 MiB), after
// which blocks of a run's size (patterns, matrices, MUMPS's work arrays) come from the heap and stay in
// the process once freed, fragmenting it; fixed thresholds hand them back to the system. Measured on
// the paper's scene at 240 x 80: peak resident memory 233 -> 213 MiB, at no measurable cost in time
// (the extra page faults are those of the set-up's own allocations, about 30 000). Blocks under 4 MiB
// (a field's vectors) keep coming from the heap, whose top is trimmed only past 8 MiB free, so that a
// step's vectors are not handed back and faulted in again.
void return_large_blocks_to_the_system() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 4 << 20);
  mallopt(M_TRIM_THRESHOLD, 8 << 20);
#endif
}

// The library's version and the BLAS kernels this machine runs: two machines agree to the bit only when
// both lines agree (docs/design.md, "Round-off across machines").
int version() {
  std::printf("piezocontact %s\nBLAS: %s\n", pc::library_version(), pc::blas_info().describe().c_str());
  return 0;
}

int main(int argc, char** argv) {
  return_large_blocks_to_the_system();
  pc::processes::initialize(&argc, &argv);  // under mpirun; nothing on one process
  if (argc == 2 && std::string(argv[1]) == "--version") return version();
  if (argc >= 2 && (std::string(argv[1]) == "list" || std::string(argv[1]) == "describe")) {
    try {
      return catalog(argv[1], argc, argv);
    } catch (const pc::Error& e) {
      std::fprintf(stderr, "error: %s\n", e.what());
      return 1;
    }
  }
  if (argc < 3) return usage();
  const std::string command = argv[1];
  if (command != "run" && command != "check" && command != "modes") return usage();
  const std::string scene_path = argv[2];
  std::vector<std::string> overrides, plugins;
  pc::SceneRunOptions options;
  options.output_directory = "results";
  pc::ModalOptions modal;
  bool open_circuit = false;
  for (int i = 3; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "error: %s needs a value\n", arg.c_str());
        std::exit(usage());
      }
      return argv[++i];
    };
    if (arg == "--out") {
      options.output_directory = value();
      if (options.output_directory.empty()) {
        std::fprintf(stderr, "error: --out is empty: name the directory to write the results into\n");
        return 1;
      }
    } else if (arg == "--set")
      overrides.push_back(value());
    else if (arg == "--plugin")
      plugins.push_back(value());
    else if (arg == "--only")
      options.only.push_back(value());
    else if (arg == "--no-sweep")
      options.sweep = false;
    else if (arg == "--quiet")
      options.progress = false;
    else if (arg == "--resume")
      options.resume = true;
    else if (arg == "--target-error" && command == "run")
      overrides.push_back("target_error=" + target_error_fraction(value()));
    else if (arg == "--count" && command == "modes")
      modal.modes = number<int>(arg, value());
    else if (arg == "--shift" && command == "modes")
      modal.shift_hz = number<double>(arg, value());
    else if (arg == "--open-circuit" && command == "modes")
      open_circuit = true;
    else {
      std::fprintf(stderr, "error: unknown option '%s'\n", arg.c_str());
      return usage();
    }
  }
  try {
    for (const std::string& plugin : plugins) pc::load_plugin(plugin);  // before the scene names its laws
    const pc::Scene scene = pc::load_scene_file(scene_path, overrides);
    if (command == "modes") {
      const std::string directory =
          options.output_directory + "/" + scene.name + (open_circuit ? "/modes_open_circuit" : "/modes");
      const pc::ModalResult modes = pc::write_scene_modes(scene, directory, modal, open_circuit);
      if (pc::processes::is_writer()) {
        std::printf("%zu modes of '%s' (%s, %s electrodes), nearest to %g Hz, in %d Lanczos restarts and %d solves:\n",
                    modes.frequencies_hz.size(), scene.name.c_str(), scene.mesh_description.c_str(),
                    open_circuit ? "open-circuit" : "short-circuit", modal.shift_hz, modes.lanczos_iterations,
                    modes.operator_applications);
        for (size_t k = 0; k < modes.frequencies_hz.size(); ++k)
          std::printf("  mode %zu: %.6g Hz\n", k + 1, modes.frequencies_hz[k]);
        std::printf("shapes and table in %s\n", directory.c_str());
      }
      return 0;
    }
    if (command == "check") {
      // Building each foundation's model runs every check the run would make before its first step. The
      // prediction is the run's own (its first progress line), of the largest foundation's model.
      int dofs = 0;
      pc::TimeEstimate predicted;
      for (const pc::SceneFoundation& f : scene.foundations) {
        pc::FoundationRun run(scene, f);
        const pc::TimeEstimate estimate = pc::estimate_run_seconds(run.model(), scene.steps);
        if (estimate.seconds < predicted.seconds) continue;
        predicted = estimate;
        dofs = pc::model_dofs(run.model());
      }
      if (pc::processes::is_writer())
        std::printf(
            "scene '%s' is valid: %s, %zu foundation(s), %d steps to T = %g s; %d dofs, predicted %s per "
            "foundation (%s)\n",
            scene.name.c_str(), scene.mesh_description.c_str(), scene.foundations.size(), scene.steps, scene.end_time,
            dofs, pc::describe_duration(predicted.seconds).c_str(), predicted.basis);
      return 0;
    }
    // A name the scene lacks is refused with the ones it has, and the nearest if one is close.
    std::vector<std::string> foundations;
    std::string listed;
    for (const auto& f : scene.foundations) {
      foundations.push_back(f.name);
      listed += (listed.empty() ? "" : ", ") + f.name;
    }
    for (const std::string& name : options.only)
      pc::require(std::find(foundations.begin(), foundations.end(), name) != foundations.end(),
                  "--only: the scene has no foundation '", name, "' (it has: ", listed, ")",
                  pc::did_you_mean(name, foundations));
    pc::install_interrupt_handlers();  // SIGINT, SIGTERM: stop after the current step, results written
    return pc::run_scene_outcome(scene, options).exit_status();
  } catch (const pc::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return failed();
  } catch (const std::filesystem::filesystem_error& e) {
    // Whatever the runner did not turn into a pc::Error: a clear message and exit 1, never an abort.
    std::fprintf(stderr, "error: writing the results into --out '%s' failed: %s\n", options.output_directory.c_str(),
                 e.what());
    return failed();
  } catch (const pc::OutOfMemory& e) {  // what ran out of memory, where the library could tell
    std::fprintf(stderr, "error: %s\n", e.what());
    return failed();
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "error: out of memory (std::bad_alloc): the scene needs more memory than the machine has\n");
    return failed();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return failed();
  }
}
