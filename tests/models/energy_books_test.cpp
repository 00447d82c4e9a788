// The energy books under backward Euler:
//  1. the paper's scene (conductive foundation): every step's books balance to Newton's tolerance, the
//     dissipations are not negative, the piezoelectric coupling exchanges energy without keeping any, and
//     the scheme's numerical dissipation is first order: it halves with the step;
//  2. the clamped capacitor under a voltage ramp, in closed form: it stores 1/2 C V^2, the electrode
//     works sum V_n C dV_n = 1/2 C V^2 + 1/2 C sum dV^2, and the difference is the numerical dissipation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "assembly/mesh_generators.hpp"
#include "bricks/piezo_materials.hpp"
#include "models/piezo/energy_books.hpp"
#include "models/scene/scene.hpp"
#include "support/clamped_capacitor.hpp"
#include "support/run_model.hpp"
#include "support/shipped_scenes.hpp"

namespace pc {
namespace {

// The paper's scene (insulated or conductive) on a coarse mesh, run for `steps` steps of its time span.
EnergyBalance paper_books(int steps, const std::string& foundation, bool check_every_step) {
  const Scene scene = load_scene_file(testing::kPaperScene, {"mesh.nx=12", "mesh.ny=4"});
  PiezoContactSpec spec = scene.spec;
  spec.foundation = find_foundation(scene, foundation).law;
  PiezoContactModel built = build_piezo_contact_model(spec);
  EnergyBooks books(built);
  bool started = false;
  testing::run(built, scene.end_time, steps, [&](const Model& m) {
    if (!started) {
      books.start(m);
      started = true;
      return;
    }
    const EnergyBalance& b = books.record(m);
    if (!check_every_step) return;
    EXPECT_LE(std::abs(b.balance), 1e-8 * b.scale()) << "t = " << m.time();
    EXPECT_GE(b.viscous_dissipation, 0);
    EXPECT_GE(b.contact_dissipation, 0);
    EXPECT_GE(b.numerical_dissipation, 0);
    EXPECT_LE(std::abs(b.coupling), 1e-10 * b.scale()) << "t = " << m.time();
  });
  return books.totals();
}

TEST(EnergyBooks, PaperSceneBalancesEveryStepAndItsNumericalDissipationIsFirstOrder) {
  for (const char* foundation : {"insulated", "conductive"}) {
    SCOPED_TRACE(foundation);
    const EnergyBalance coarse = paper_books(20, foundation, true);
    EXPECT_GT(coarse.external_work, 0);  // the traction pushes the strip down
    EXPECT_GT(coarse.viscous_dissipation, 0);
    const EnergyBalance fine = paper_books(40, foundation, false), finer = paper_books(80, foundation, false);
    const double ratio = fine.numerical_dissipation / finer.numerical_dissipation;
    std::printf("%s: numerical dissipation %.4e, %.4e, %.4e with 20, 40, 80 steps\n", foundation,
                coarse.numerical_dissipation, fine.numerical_dissipation, finer.numerical_dissipation);
    EXPECT_NEAR(ratio, 2.0, 0.25) << fine.numerical_dissipation << " -> " << finer.numerical_dissipation;
  }
}

TEST(EnergyBooks, ClampedCapacitorStoresHalfCVSquaredAndItsElectrodeWorksTheRest) {
  const double volts = 100, ramp = 1e-3;
  const int steps = 8;
  const testing::ClampedCapacitor capacitor;
  PiezoContactModel built = build_piezo_contact_model(capacitor.spec(volts, ramp, true));
  EnergyBooks books(built);
  bool started = false;
  testing::run(built, ramp, steps, [&](const Model& m) {
    if (started) {
      books.record(m);
    } else {
      books.start(m);
      started = true;
    }
  });
  const double capacitance = capacitor.capacitance(), dv = volts / steps;
  const EnergyBalance& b = books.totals();
  const double stored = 0.5 * capacitance * volts * volts;
  EXPECT_NEAR(b.electric, stored, 1e-10 * stored);
  EXPECT_NEAR(b.numerical_dissipation, 0.5 * capacitance * dv * dv * steps, 1e-9 * stored);
  EXPECT_NEAR(b.boundary_work, stored + 0.5 * capacitance * dv * dv * steps, 1e-9 * stored);
  EXPECT_LE(std::abs(b.kinetic), 1e-20 * stored);  // clamped: no motion but round-off
  EXPECT_LE(std::abs(b.balance), 1e-10 * stored);
}

}  // namespace
}  // namespace pc
