#include "models/scene/target_error.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <tuple>

#include "assembly/error.hpp"
#include "models/scene/memory_estimate.hpp"
#include "models/scene/scene_runner.hpp"
#include "models/scene/target_error_format.hpp"
#include "models/scene/target_error_rates.hpp"
#include "models/scene/time_estimate.hpp"

namespace pc {
namespace {

constexpr double kMaxDofs = 4e6;
constexpr double kTightening = 8;  // the time pilot's tolerance is the others' over this
// The choice aims at kMargin times the target: the 1 % choice on the paper scene reached 1.04 % aiming at
// 1 %, its time estimate 1.6 times the predicted one.
constexpr double kMargin = 0.8;
// With a rate far below the theory's (models/scene/target_error_rates.hpp), candidates go no further from
// the pilots than this: 4 times the finer pilot's cells along an axis, a tolerance 64 times smaller.
constexpr double kFarMeshReach = 4, kFarToleranceReach = kTightening * kTightening;

// The largest estimates of a pilot over its run, over the foundations run, its step attempts and wall
// time (each foundation's: its model's build and run).
struct PilotResult {
  int dofs = 0, attempts = 0;
  double space = 0, time = 0, seconds = 0;
  std::map<std::string, double> foundation_seconds;
};

int scaled(int n, double factor) { return n > 0 ? std::max(1, int(std::lround(n * factor))) : 0; }

// A setting: the order, the scheme, the mesh (cells along each axis scaled by factor) and the tolerance.
TargetErrorChoice setting(int order, const std::string& scheme, int nx, int ny, int nz, double factor,
                          double tolerance) {
  TargetErrorChoice c;
  c.order = order;
  c.scheme = scheme;
  c.nx = scaled(nx, factor);
  c.ny = scaled(ny, factor);
  c.nz = scaled(nz, factor);
  c.tolerance = tolerance;
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
    const auto began = std::chrono::steady_clock::now();
    FoundationRun run(pilot, f);
    const FoundationRunResult r = run.run("", false);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    require(r.completed, "target error: the pilot run (", p.description(), ") of the ", f.name,
            " foundation did not complete: ", r.message);
    worst.dofs = r.ndof;
    worst.attempts = std::max(worst.attempts, r.steps + r.rejections + r.cutbacks);
    worst.space = std::max(worst.space, r.space_error_peak());
    worst.time = std::max(worst.time, r.time_error_peak);
    worst.seconds += seconds;
    worst.foundation_seconds[f.name] += seconds;
  }
  return worst;
}

int scheme_order(const std::string& scheme) { return scheme == "bdf2" ? 2 : 1; }

// A measured exponent, from two results a factor `apart` apart, and the one used: within [low, high].
struct Rate {
  double measured = 0, used = 0;
};
Rate rate_of(double coarse, double fine, double apart, double low, double high) {
  const double measured = coarse > 0 && fine > 0 ? std::log(coarse / fine) / std::log(apart) : high;
  return {measured, std::clamp(measured, low, high)};
}

// Per order (P1 with backward Euler, P2 with BDF2): a quarter and half the scene's cells at the pilot
// tolerance, for the spatial rate; half the cells at a tolerance kTightening times smaller, for the time
// error's and the step count's response to the tolerance. The rates against the theory's: the spatial
// one in the cells, the temporal one in the step attempts.
struct PilotSet {
  Pilot coarse, fine, tight;
  Rate space, time, steps;
  RateCheck space_check, time_check;
};

void check_rates(PilotSet& set) {
  const TargetErrorChoice& s = set.fine.setting;
  const std::string name = message("P", s.order, " ", s.scheme, ": the ");
  set.space_check = check_rate(name + "spatial rate", {double(set.coarse.setting.nx), double(s.nx)},
                               {set.coarse.result.space, set.fine.result.space}, s.order);
  set.time_check = check_rate(name + "time rate", {double(set.fine.result.attempts), double(set.tight.result.attempts)},
                              {set.fine.result.time, set.tight.result.time}, scheme_order(s.scheme));
}

std::vector<PilotSet> run_pilots(const Scene& scene, const std::vector<std::string>& only, double tolerance,
                                 bool progress) {
  std::vector<PilotSet> pilots;
  for (const auto& [order, scheme] : {std::pair{1, "backward_euler"}, std::pair{2, "bdf2"}}) {
    PilotSet set;
    for (auto [pilot, scale, tol] : {std::tuple{&set.coarse, 0.25, tolerance}, std::tuple{&set.fine, 0.5, tolerance},
                                     std::tuple{&set.tight, 0.5, tolerance / kTightening}}) {
      pilot->setting = setting(order, scheme, scene.nx, scene.ny, scene.nz, scale, tol);
      pilot->result = run_pilot(scene, only, pilot->setting);
      if (progress)
        std::printf("  target error pilot: %s: %d dofs, %d steps, space %s, time %s, %s s\n",
                    pilot->setting.description().c_str(), pilot->result.dofs, pilot->result.attempts,
                    percent(pilot->result.space).c_str(), percent(pilot->result.time).c_str(),
                    three_digits(pilot->result.seconds).c_str());
    }
    // Space: a singular solution gives less than the theory, a coarse pilot may suggest more. Time: the
    // error follows the tolerance at most proportionally (the controller's aim), the steps as the local
    // error's order (k^(q+1): tolerance^(-1/(q+1))) or faster where the transient is unresolved.
    const int q = scheme_order(scheme);
    set.space = rate_of(set.coarse.result.space, set.fine.result.space, 2, 0.25, order);
    set.time = rate_of(set.fine.result.time, set.tight.result.time, kTightening, 0.25, 1);
    set.steps = rate_of(set.tight.result.attempts, set.fine.result.attempts, kTightening, 1.0 / (q + 1), 1);
    check_rates(set);
    pilots.push_back(set);
  }
  return pilots;
}

// The fitted rates against the theory's, and the exponents the predictions use, on one line.
std::string rates_text(const std::vector<PilotSet>& pilots) {
  std::string text = "rates (theory):";
  for (const PilotSet& p : pilots)
    text += message(text.back() == ':' ? " " : "; ", "P", p.fine.setting.order, " ", p.fine.setting.scheme, " space ",
                    three_digits(p.space_check.measured), " (", three_digits(p.space_check.theory), "), time ",
                    three_digits(p.time_check.measured), " (", three_digits(p.time_check.theory),
                    "), time error ~ tolerance^", three_digits(p.time.used), ", steps ~ tolerance^-",
                    three_digits(p.steps.used));
  return text;
}

// A rate far below the theory's: said, with the fallback.
std::vector<std::string> rate_warnings(const std::vector<PilotSet>& pilots) {
  std::vector<std::string> warnings;
  for (const PilotSet& p : pilots) {
    if (p.space_check.far_below)
      warnings.push_back(message("warning: target error: ", p.space_check.problem, ": its meshes are extrapolated ",
                                 "with the measured rate, and to at most ", kFarMeshReach, " times the pilot's cells"));
    if (p.time_check.far_below)
      warnings.push_back(message("warning: target error: ", p.time_check.problem,
                                 ": its tolerances are extrapolated with the measured exponents, and to at most ",
                                 kFarToleranceReach, " times below the pilots'"));
  }
  return warnings;
}

// The least predicted cost that reaches the target, and the closest to it (for the refusal).
struct Search {
  TargetErrorChoice best, closest;
  double best_seconds = std::numeric_limits<double>::infinity(),
         closest_error = std::numeric_limits<double>::infinity();
};

void search_candidates(const PilotSet& set, int dim, double memory, double aim, Search& found) {
  const Pilot& fine = set.fine;
  const int order = fine.setting.order;
  for (int j = -2; j <= 10; ++j) {
    const double factor = std::pow(2.0, j / 2.0);  // over the finer pilot's mesh, 1/2 to 32
    if (set.space_check.far_below && factor > kFarMeshReach) break;
    const double space = fine.result.space * std::pow(factor, -set.space.used);
    const double dofs = fine.result.dofs * std::pow(factor, dim);
    const int cells[3] = {scaled(fine.setting.nx, factor), scaled(fine.setting.ny, factor),
                          scaled(fine.setting.nz, factor)};
    if (dofs > kMaxDofs || (memory > 0 && estimate_structured_run(dim, cells, order).bytes > memory)) break;
    for (int k = -2; k <= 30; ++k) {  // tolerances from twice the pilots' down, in steps of 2^(1/2)
      const double tolerance = fine.setting.tolerance * std::pow(2.0, -k / 2.0);
      if (tolerance > 0.5 || tolerance < 1e-12) continue;
      const double shrink = fine.setting.tolerance / tolerance;
      if (set.time_check.far_below && shrink > kFarToleranceReach) break;
      const double time = fine.result.time * std::pow(shrink, -set.time.used);
      const double attempts = fine.result.attempts * std::pow(shrink, set.steps.used);
      TargetErrorChoice c =
          setting(order, fine.setting.scheme, fine.setting.nx, fine.setting.ny, fine.setting.nz, factor, tolerance);
      c.dofs = int(dofs);
      c.steps = int(std::lround(attempts));
      c.predicted_space = space;
      c.predicted_time = time;
      c.predicted_seconds = estimate_run_seconds(dim, dofs, std::max(1, c.steps)).seconds;
      if (space + time <= aim && c.predicted_seconds < found.best_seconds) {
        found.best = c;
        found.best_seconds = c.predicted_seconds;
      }
      // The closest, for the refusal: within 5 % of the least error, the cheapest.
      const double error = space + time;
      if (error < 0.95 * found.closest_error ||
          (error <= 1.05 * found.closest_error && c.predicted_seconds < found.closest.predicted_seconds)) {
        found.closest = c;
        found.closest_error = std::min(found.closest_error, error);
      }
    }
  }
}

// What a candidate may use: solver.max_memory_gib, or what the machine has (the scene's own check).
double candidate_memory(const Scene& scene) {
  if (const auto solver = scene.json.find("solver"))
    if (const auto cap = solver->find("max_memory_gib")) return cap->as_positive() * 1073741824.0;
  return available_memory_bytes();
}

}  // namespace

std::vector<std::string> TargetErrorChoice::overrides() const {
  std::vector<std::string> o = {"mesh.nx=" + std::to_string(nx), "mesh.ny=" + std::to_string(ny)};
  if (nz > 0) o.push_back("mesh.nz=" + std::to_string(nz));
  o.insert(o.end(), {"mesh.order=" + std::to_string(order), "time.scheme=" + scheme,
                     "time.adaptive=" + message(tolerance), "output.space_error_every=1"});
  return o;
}

std::string TargetErrorChoice::description() const {
  return message("P", order, " on ", nx, " x ", ny, nz > 0 ? message(" x ", nz) : std::string(), " cells, ", scheme,
                 ", adaptive ", three_digits(tolerance), steps > 0 ? message(" (~", steps, " steps)") : std::string());
}

double TargetErrorChoice::pilots_seconds_of(const std::string& foundation) const {
  const auto it = foundation_pilots_seconds.find(foundation);
  return it == foundation_pilots_seconds.end() ? 0 : it->second;
}

TargetErrorChoice choose_for_target_error(const Scene& scene, const std::vector<std::string>& only, bool progress) {
  require(scene.target_error.has_value(), "target error: the scene has no target_error");
  require(!scene.file.empty(), "target error: the pilots reload the scene from its file, and this scene has none");
  const double target = *scene.target_error;
  const auto began = std::chrono::steady_clock::now();
  const std::vector<PilotSet> pilots = run_pilots(scene, only, std::min(0.5, target), progress);
  Search found;
  found.closest.predicted_seconds = std::numeric_limits<double>::infinity();
  for (const PilotSet& set : pilots)
    search_candidates(set, scene.spec.mesh->dim(), candidate_memory(scene), kMargin * target, found);
  const double pilots_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  const std::string rates = rates_text(pilots);
  const std::vector<std::string> warnings = rate_warnings(pilots);
  std::string warnings_text;
  for (const std::string& w : warnings) warnings_text += "; " + w;
  const TargetErrorChoice& closest = found.closest;
  require(std::isfinite(found.best_seconds), "target error ", three_digits(target),
          ": no setting that fits in memory (and ", kMaxDofs, " dofs) is predicted to reach ",
          percent(kMargin * target), " (the target times the safety margin ", kMargin, "); the closest, ",
          closest.description(), ", is predicted to reach ", percent(closest.predicted_space + closest.predicted_time),
          " (space ", percent(closest.predicted_space), " + time ", percent(closest.predicted_time), ") in ",
          three_digits(closest.predicted_seconds),
          " s. Raise the target, or the memory (solver.max_memory_gib), or run that setting with --set (pilots ",
          three_digits(pilots_seconds), " s, ", rates, warnings_text, ")");
  TargetErrorChoice best = found.best;
  best.target = target;
  best.margin = kMargin;
  best.pilots_seconds = pilots_seconds;
  for (const PilotSet& set : pilots)
    for (const Pilot* p : {&set.coarse, &set.fine, &set.tight})
      for (const auto& [foundation, seconds] : p->result.foundation_seconds)
        best.foundation_pilots_seconds[foundation] += seconds;
  best.rates = rates;
  best.warnings = warnings;
  best.explanation = message(
      "chose ", best.description(), ", aiming at ", percent(kMargin * target), " (safety margin ", kMargin,
      "): predicted ", percent(best.predicted_space + best.predicted_time), " (space ", percent(best.predicted_space),
      " + time ", percent(best.predicted_time), ") in ", three_digits(best.predicted_seconds), " s, ",
      three_digits(best.predicted_seconds + pilots_seconds), " s with the pilots, the least predicted cost");
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
