#include "models/scene/target_error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "assembly/error.hpp"
#include "models/scene/memory_estimate.hpp"
#include "models/scene/scene_runner.hpp"
#include "models/scene/time_estimate.hpp"

namespace pc {
namespace {

constexpr double kMaxDofs = 4e6;

// The largest estimates of a pilot's final state, over the foundations run.
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
    for (const auto& [field, relative] : r.space_error) worst.space = std::max(worst.space, relative);
    for (const FieldTimeError& e : r.time_error) worst.time = std::max(worst.time, e.global);
  }
  return worst;
}

int scheme_order(const std::string& scheme) { return scheme == "bdf2" ? 2 : 1; }

}  // namespace

std::vector<std::string> TargetErrorChoice::overrides() const {
  std::vector<std::string> o = {"mesh.nx=" + std::to_string(nx), "mesh.ny=" + std::to_string(ny)};
  if (nz > 0) o.push_back("mesh.nz=" + std::to_string(nz));
  o.insert(o.end(), {"mesh.order=" + std::to_string(order), "time.scheme=" + scheme, "time.steps=" + std::to_string(steps)});
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
  // Two mesh sizes per order: a quarter of the scene's and half of it.
  std::vector<Pilot> pilots;
  for (const auto& [order, scheme] : {std::pair{1, "backward_euler"}, std::pair{2, "bdf2"}})
    for (double scale : {0.25, 0.5}) {
      Pilot p{setting(order, scheme, scene.nx, scene.ny, scene.nz, scale, pilot_steps), {}};
      p.result = run_pilot(scene, only, p.setting);
      if (progress)
        std::printf("  target error pilot: %s: %d dofs, space %.3g, time %.3g\n", p.setting.description().c_str(),
                    p.result.dofs, p.result.space, p.result.time);
      pilots.push_back(p);
    }

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
  for (int order : {1, 2}) {
    const Pilot& coarse = pilots[size_t(2 * (order - 1))];
    const Pilot& fine = pilots[size_t(2 * (order - 1) + 1)];
    // Cells per axis doubled between the pilots: the rate of the spatial estimate in the cell size.
    const double measured = coarse.result.space > 0 && fine.result.space > 0 ? std::log2(coarse.result.space / fine.result.space) : order;
    const double rate = std::clamp(measured, 0.25, double(order));
    rates += message(rates.empty() ? "" : "; ", "P", order, " space ", coarse.result.space, " -> ", fine.result.space,
                     " (rate ", measured, ", used ", rate, ")");
    for (const std::string scheme : {"backward_euler", "bdf2"}) {
      // The time estimate of this scheme: from the pilots that ran it (P1 backward Euler, P2 BDF2).
      const Pilot& timed = pilots[scheme == "bdf2" ? 3 : 1];
      for (int j = -2; j <= 10; ++j) {
        const double factor = std::pow(2.0, j / 2.0);  // over the finer pilot's mesh, 1/2 to 32
        const double space = fine.result.space * std::pow(factor, -rate);
        const double dofs = fine.result.dofs * std::pow(factor, dim);
        const int cells[3] = {scaled(fine.setting.nx, factor), scaled(fine.setting.ny, factor), scaled(fine.setting.nz, factor)};
        if (dofs > kMaxDofs || (memory > 0 && estimate_structured_run(dim, cells, order).bytes > memory)) break;
        for (int k = 0; k <= 22; ++k) {
          // From half the pilots' steps up: the time model is not trusted far below what was measured.
          const int steps = int(std::lround(std::max(10, pilot_steps / 2) * std::pow(2.0, k / 2.0)));
          const double time = timed.result.time * std::pow(double(pilot_steps) / steps, scheme_order(scheme));
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
  const std::string pilots_text = message("pilots with ", pilot_steps, " steps: ", rates, "; time: backward Euler ",
                                          pilots[1].result.time, ", BDF2 ", pilots[3].result.time);
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
