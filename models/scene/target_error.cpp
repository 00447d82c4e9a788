#include "models/scene/target_error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <tuple>

#include "assembly/error.hpp"
#include "models/scene/memory_estimate.hpp"
#include "models/scene/scene_runner.hpp"
#include "models/scene/time_estimate.hpp"

namespace pc {
namespace {

constexpr double kMaxDofs = 4e6;

// The largest estimates of a pilot over its run, over the foundations run.
struct PilotResult {
  int dofs = 0;
  double space = 0, time = 0;
};

int scaled(int n, double factor) { return n > 0 ? std::max(1, int(std::lround(n * factor))) : 0; }

// A setting: the order, the scheme, the mesh (cells along each axis scaled by factor) and the steps.
TargetErrorChoice setting(int order, const std::string& scheme, int nx, int ny, int nz, double factor, int steps) {
  TargetErrorChoice c;
  c.order = order;
  c.scheme = scheme;
  c.nx = scaled(nx, factor);
  c.ny = scaled(ny, factor);
  c.nz = scaled(nz, factor);
  c.steps = steps;
  return c;
}

struct Pilot {
  TargetErrorChoice setting;
  PilotResult result;
};

PilotResult run_pilot(const Scene& scene, const std::vector<std::string>& only, const TargetErrorChoice& p) {
  std::vector<std::string> overrides = scene.overrides;
  for (const std::string& o : p.overrides()) overrides.push_back(o);
  Scene pilot = load_scene_file(scene.file, overrides);
  pilot.target_error.reset();
  PilotResult worst;
  for (const SceneFoundation& f : pilot.foundations) {
    if (!only.empty() && std::find(only.begin(), only.end(), f.name) == only.end()) continue;
    FoundationRun run(pilot, f);
    const FoundationRunResult r = run.run("", false);
    require(r.completed, "target error: the pilot run (", p.description(), ") of the ", f.name,
            " foundation did not complete: ", r.message);
    worst.dofs = r.ndof;
    worst.space = std::max(worst.space, r.space_error_peak());
    worst.time = std::max(worst.time, r.time_error_peak);
  }
  return worst;
}

int scheme_order(const std::string& scheme) { return scheme == "bdf2" ? 2 : 1; }

}  // namespace

std::vector<std::string> TargetErrorChoice::overrides() const {
  std::vector<std::string> o = {"mesh.nx=" + std::to_string(nx), "mesh.ny=" + std::to_string(ny)};
  if (nz > 0) o.push_back("mesh.nz=" + std::to_string(nz));
  o.insert(o.end(), {"mesh.order=" + std::to_string(order), "time.scheme=" + scheme, "time.steps=" + std::to_string(steps),
                     "output.space_error_every=1"});
  return o;
}

std::string TargetErrorChoice::description() const {
  return message("P", order, " on ", nx, " x ", ny, nz > 0 ? message(" x ", nz) : std::string(), " cells, ", scheme, ", ",
                 steps, " steps");
}

TargetErrorChoice choose_for_target_error(const Scene& scene, const std::vector<std::string>& only, bool progress) {
  require(scene.target_error.has_value(), "target error: the scene has no target_error");
  require(!scene.file.empty(), "target error: the pilots reload the scene from its file, and this scene has none");
  const double target = *scene.target_error;
  const int dim = scene.spec.mesh->dim();
  const int pilot_steps = std::max(20, scene.steps / 5);
  // Per order (P1 with backward Euler, P2 with BDF2): a quarter and half the scene's cells along each
  // axis with pilot_steps, for the spatial rate; half the cells with twice the steps, for the temporal one.
  struct PilotSet {
    Pilot coarse, fine, longer;
  };
  std::vector<PilotSet> pilots;
  for (const auto& [order, scheme] : {std::pair{1, "backward_euler"}, std::pair{2, "bdf2"}}) {
    PilotSet set;
    for (auto [pilot, scale, steps] : {std::tuple{&set.coarse, 0.25, pilot_steps}, std::tuple{&set.fine, 0.5, pilot_steps},
                                       std::tuple{&set.longer, 0.5, 2 * pilot_steps}}) {
      pilot->setting = setting(order, scheme, scene.nx, scene.ny, scene.nz, scale, steps);
      pilot->result = run_pilot(scene, only, pilot->setting);
      if (progress)
        std::printf("  target error pilot: %s: %d dofs, space %.3g, time %.3g\n", pilot->setting.description().c_str(),
                    pilot->result.dofs, pilot->result.space, pilot->result.time);
    }
    pilots.push_back(set);
  }
  // A rate from two estimates a factor 2 apart, kept within [0.25, the theoretical order]: a singular
  // solution or order reduction (a stiff contact) gives less than the theory, a pilot on the coarse side
  // may suggest more.
  const auto rate_of = [](double coarse, double fine, int theory) {
    const double measured = coarse > 0 && fine > 0 ? std::log2(coarse / fine) : theory;
    return std::pair{measured, std::clamp(measured, 0.25, double(theory))};
  };

  // What a candidate may use: solver.max_memory_gib, or what the machine has (the scene's own check).
  double memory = available_memory_bytes();
  if (const auto solver = scene.json.find("solver"))
    if (const auto cap = solver->find("max_memory_gib")) memory = cap->as_positive() * 1073741824.0;
  TargetErrorChoice best;
  best.target = target;
  double best_seconds = std::numeric_limits<double>::infinity();
  TargetErrorChoice closest;  // the least predicted error, if nothing reaches the target
  closest.predicted_seconds = std::numeric_limits<double>::infinity();
  double closest_error = std::numeric_limits<double>::infinity();
  std::string rates;
  for (const PilotSet& set : pilots) {
    const int order = set.fine.setting.order;
    const Pilot& fine = set.fine;
    const auto [measured_space, space_rate] = rate_of(set.coarse.result.space, fine.result.space, order);
    rates += message(rates.empty() ? "" : "; ", "P", order, " space ", set.coarse.result.space, " -> ", fine.result.space,
                     " (rate ", measured_space, ", used ", space_rate, ")");
    for (const PilotSet& timed : pilots) {  // each scheme's time error, from the pilots that ran it
      const std::string& scheme = timed.fine.setting.scheme;
      const auto [measured_time, time_rate] =
          rate_of(timed.fine.result.time, timed.longer.result.time, scheme_order(scheme));
      if (order == 1)
        rates += message("; ", scheme, " time ", timed.fine.result.time, " -> ", timed.longer.result.time, " (rate ",
                         measured_time, ", used ", time_rate, ")");
      for (int j = -2; j <= 10; ++j) {
        const double factor = std::pow(2.0, j / 2.0);  // over the finer pilot's mesh, 1/2 to 32
        const double space = fine.result.space * std::pow(factor, -space_rate);
        const double dofs = fine.result.dofs * std::pow(factor, dim);
        const int cells[3] = {scaled(fine.setting.nx, factor), scaled(fine.setting.ny, factor), scaled(fine.setting.nz, factor)};
        if (dofs > kMaxDofs || (memory > 0 && estimate_structured_run(dim, cells, order).bytes > memory)) break;
        for (int k = 0; k <= 22; ++k) {
          // From half the pilots' steps up: the time model is not trusted far below what was measured.
          const int steps = int(std::lround(std::max(10, pilot_steps / 2) * std::pow(2.0, k / 2.0)));
          const double time = timed.longer.result.time * std::pow(2.0 * pilot_steps / steps, time_rate);
          const double seconds = estimate_run_seconds(dim, dofs, steps).seconds;
          TargetErrorChoice c = setting(order, scheme, fine.setting.nx, fine.setting.ny, fine.setting.nz, factor, steps);
          c.target = target;
          c.dofs = int(dofs);
          c.predicted_space = space;
          c.predicted_time = time;
          c.predicted_seconds = seconds;
          if (space + time <= target && seconds < best_seconds) {
            best = c;
            best_seconds = seconds;
          }
          // The closest, for the refusal: within 5 % of the least error, the cheapest.
          const double error = space + time;
          if (error < 0.95 * closest_error || (error <= 1.05 * closest_error && seconds < closest.predicted_seconds)) {
            closest = c;
            closest_error = std::min(closest_error, error);
          }
        }
      }
    }
  }
  const std::string pilots_text = message("pilots with ", pilot_steps, " and ", 2 * pilot_steps, " steps: ", rates);
  require(std::isfinite(best_seconds), "target error ", target, ": no setting that fits in memory (and ", kMaxDofs,
          " dofs) is predicted to reach it; the closest, ", closest.description(), ", is predicted to reach ",
          closest.predicted_space + closest.predicted_time, " (space ", closest.predicted_space, " + time ",
          closest.predicted_time, ") in ", closest.predicted_seconds, " s. Raise the target, or the memory ",
          "(solver.max_memory_gib), or run that setting with --set (", pilots_text, ")");
  best.explanation = message("chose ", best.description(), ": predicted space ", best.predicted_space, " + time ",
                             best.predicted_time, " <= ", target, " in ", best.predicted_seconds,
                             " s, the least predicted cost (", pilots_text, ")");
  return best;
}

Scene scene_for_target_error(const Scene& scene, const std::vector<std::string>& only, bool progress) {
  const TargetErrorChoice choice = choose_for_target_error(scene, only, progress);
  std::vector<std::string> overrides = scene.overrides;
  for (const std::string& o : choice.overrides()) overrides.push_back(o);
  Scene chosen = load_scene_file(scene.file, overrides);
  chosen.target_choice = choice;
  return chosen;
}

}  // namespace pc
