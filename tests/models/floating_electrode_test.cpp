// Floating electrodes (models/piezo/electrodes.hpp: one unknown potential over the region, a given net
// charge) against closed forms, on models whose fields are uniform so that P1 holds them to round-off:
//  1. a clamped capacitor whose top electrode is charged by a ramp Q(t) rises to V = Q / C at every step;
//  2. a free PZT bar compressed along its poling axis, open-circuit (zero charge), shows the sensor voltage
//     V = g33 sigma h (g33 = d33 / eps^T) and strains by s33^D sigma, stiffer than the short-circuited bar's
//     s33^E sigma (s^D = s^E - d^2 / eps^T): the electromechanical coupling k33^2 = 1 - s^D / s^E;
//  3. bad input: a floating electrode over a grounded region is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "assembly/error.hpp"
#include "assembly/mesh_generators.hpp"
#include "bricks/dirichlet_brick.hpp"
#include "bricks/piezo_materials.hpp"
#include "models/piezo/electrodes.hpp"
#include "models/piezo/energy_books.hpp"
#include "models/piezo/piezo_contact_recipe.hpp"
#include "support/clamped_capacitor.hpp"
#include "support/piezo_circuit.hpp"
#include "support/run_model.hpp"

namespace pc {
namespace {

using testing::run;

TEST(FloatingElectrode, ChargedCapacitorRisesToChargeOverCapacitanceAtEveryStep) {
  const double ramp = 1e-3;
  const testing::ClampedCapacitor capacitor;
  const double capacitance = capacitor.capacitance(), full_charge = capacitance * 100;
  PiezoContactSpec spec = capacitor.spec(0, ramp, false);
  spec.electrodes = {floating_electrode("top", "top", TimeFunction::ramp(full_charge, ramp))};
  PiezoContactModel built = build_piezo_contact_model(spec);
  ElectrodeMeter meter(spec.electrodes);
  std::vector<ElectrodeReading> readings;
  run(built, ramp, 4, [&](const Model& m) { readings.push_back(meter.read(m)[0]); });
  ASSERT_EQ(readings.size(), 5u);
  for (size_t n = 1; n < readings.size(); ++n) {
    const double charge = full_charge * double(n) / 4;
    EXPECT_NEAR(readings[n].charge, charge, 1e-12 * full_charge);
    EXPECT_NEAR(readings[n].voltage, charge / capacitance, 1e-10 * 100) << "step " << n;
    EXPECT_NEAR(readings[n].current, full_charge / ramp, 1e-9 * full_charge / ramp) << "step " << n;
  }
  const Model& m = *built.model;
  // Every dof of the electrode holds its potential, and the grounded electrode the opposite charge.
  for (int dof : m.space("phi").dofs_on("top")) EXPECT_EQ(m.values("phi")[dof], readings.back().voltage);
  EXPECT_NEAR(electrode_charge(m, "bottom"), -full_charge, 1e-10 * full_charge);
  EXPECT_NEAR(electrode_charge(m, "top"), 0, 1e-10 * full_charge) << "the one equation of the electrode holds";
}

// A PZT-5H box poled along z, grounded on zmin, on rollers on xmin, ymin, zmin, compressed on zmax by p.
struct CompressedBar {
  static constexpr double side = 2e-3, height = 1e-3, pressure = 1e6;
  PiezoMaterialPreset material = piezo_material("PZT-5H");
  Eigen::MatrixXd s = material.c.inverse();  // s^E
  Eigen::MatrixXd d = material.e * s;        // d = e s^E
  double eps_free = material.eps(2, 2) + (material.e * d.transpose())(2, 2);

  PiezoContactModel build(bool open_circuit) const {
    const PiezoTensors t = material.tensors(3, Axis::z);
    PiezoContactSpec spec;
    spec.mesh = std::make_shared<const Mesh>(box_mesh({0, 0, 0}, {side, side, height}, 2, 2, 2, Shape::Tetrahedron));
    testing::set_piezo_tensors(spec, t, false);
    testing::set_circuit(spec, "zmin", "zmax", open_circuit);
    spec.tractions = {{"zmax", [](const double*, double, double* out) { out[0] = out[1] = 0, out[2] = -pressure; },
                       LoadTime::Constant}};
    spec.extra_bricks = [](Model& m) {
      for (int axis = 0; axis < 3; ++axis)
        m.add_brick(
            std::make_shared<DirichletBrick>(DirichletBrick::clamp("v", std::string(1, "xyz"[axis]) + "min", {axis})));
    };
    return build_piezo_contact_model(spec);
  }
  double top_displacement(const Model& m) const {
    const FESpace& space = m.space("v");
    return m.values("u")[space.dof(space.scalar_dofs_on("zmax").front(), 2)];
  }
};

TEST(FloatingElectrode, OpenCircuitBarShowsTheSensorVoltageAndTheOpenCircuitCompliance) {
  const CompressedBar bar;
  const double stress = -CompressedBar::pressure;
  PiezoContactModel open = bar.build(true), shorted = bar.build(false);
  run(open, 1, 1);
  run(shorted, 1, 1);
  // D_z = d33 sigma + eps^T E_z = 0: E_z = -d33 sigma / eps^T, V = -E_z h.
  const double g33 = bar.d(2, 2) / bar.eps_free;
  const double voltage = g33 * stress * CompressedBar::height;
  EXPECT_NEAR(electrode_potential(*open.model, "zmax"), voltage, 1e-9 * std::abs(voltage));
  EXPECT_NEAR(g33, 19.7e-3, 0.03 * 19.7e-3) << "PZT-5H's datasheet g33 is 19.7e-3 V m/N";
  const double s_short = bar.s(2, 2), s_open = bar.s(2, 2) - bar.d(2, 2) * bar.d(2, 2) / bar.eps_free;
  const double h = CompressedBar::height;
  EXPECT_NEAR(bar.top_displacement(*shorted.model), s_short * stress * h, 1e-9 * std::abs(s_short * stress * h));
  EXPECT_NEAR(bar.top_displacement(*open.model), s_open * stress * h, 1e-9 * std::abs(s_open * stress * h));
  const double k33_squared = 1 - s_open / s_short;
  EXPECT_NEAR(k33_squared, 0.75 * 0.75, 0.05) << "PZT-5H's datasheet k33 is 0.75";
  // Open, the electrode holds no charge: its one equation is the sum of the region's residuals.
  EXPECT_NEAR(electrode_charge(*open.model, "zmax"), 0, 1e-9 * std::abs(electrode_charge(*shorted.model, "zmax")));
}

TEST(FloatingElectrode, OverAGroundedRegionIsRefusedNamingBoth) {
  const testing::ClampedCapacitor capacitor;
  PiezoContactSpec spec = capacitor.spec(0, 1, false);
  spec.electrodes = {floating_electrode("bad", "bottom")};
  try {
    build_piezo_contact_model(spec);
    FAIL() << "a floating electrode on a grounded region was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("bottom"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("Dirichlet"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pc
