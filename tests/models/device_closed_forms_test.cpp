// What a device is made of, checked against closed forms on models the recipe builds:
//  1. electrodes: a clamped PZT capacitor holds Q = eps^S A V / h, and under a voltage ramp its current
//     is C dV/dt at every step (its charge is linear in time, the backward difference exact);
//  2. a free PZT bar under a voltage strokes by d33 V (d = e (c^E)^-1) and holds Q = eps^T A V / h;
//  3. the same bar blocked along its axis pushes with the blocked force d33 V A / (s33^E h);
//  4. a moving foundation: a clamped body on a foundation moving in and along its surface feels
//     p = c_nu U_f,nu(t) (the gap to the moved foundation, U_f the exact integral of V_f) and the
//     friction mu p V / sqrt(V^2 + eps^2) of the relative slip; the same with a damped normal law;
//  5. a free block pressed on a moving (compliant) foundation and held by its top feels exactly mu p.
// Every field involved is uniform or linear, so P1 reproduces it and the closed forms hold to round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "assembly/mesh_generators.hpp"
#include "bricks/dirichlet_brick.hpp"
#include "bricks/piezo_materials.hpp"
#include "bricks/voigt.hpp"
#include "models/piezo/contact_resultant.hpp"
#include "models/piezo/electrodes.hpp"
#include "models/piezo/piezo_contact_recipe.hpp"
#include "support/clamped_capacitor.hpp"
#include "support/run_model.hpp"

namespace pc {
namespace {

using testing::run;

constexpr double kVolts = 100;

// Sum of one component of a field's reactions over a region's dofs.
double reaction(const Model& m, const std::string& field, const std::string& region, int component) {
  double sum = 0;
  for (int dof : m.space(field).dofs_on(region, component)) sum += m.field_residual(field)[dof];
  return sum;
}

// ---- 1. the clamped capacitor ----------------------------------------------------------------------

TEST(DeviceClosedForms, ClampedCapacitorHoldsClampedPermittivityTimesVoltageAndItsCurrentIsCdVdt) {
  const double ramp = 1e-3;
  const testing::ClampedCapacitor capacitor;
  const PiezoContactSpec spec = capacitor.spec(kVolts, ramp, false);
  PiezoContactModel built = build_piezo_contact_model(spec);
  // Per unit depth: C = eps^S_yy L / h. Clamped, the strain is zero and D = -eps^S grad phi exactly.
  const double capacitance = capacitor.capacitance();
  ElectrodeMeter meter(spec.electrodes);
  std::vector<ElectrodeReading> readings;
  run(built, ramp, 4, [&](const Model& m) { readings.push_back(meter.read(m)[0]); });
  ASSERT_EQ(readings.size(), 5u);
  EXPECT_EQ(readings[0].charge, 0.0);
  for (size_t n = 1; n < readings.size(); ++n) {
    EXPECT_NEAR(readings[n].voltage, kVolts * double(n) / 4, 1e-12 * kVolts);
    EXPECT_NEAR(readings[n].charge, capacitance * readings[n].voltage, 1e-10 * capacitance * kVolts) << "step " << n;
    EXPECT_NEAR(readings[n].current, capacitance * kVolts / ramp, 1e-9 * capacitance * kVolts / ramp) << "step " << n;
  }
  // The grounded electrode holds the opposite charge: the body is neutral.
  EXPECT_NEAR(electrode_charge(*built.model, "bottom"), -capacitance * kVolts, 1e-10 * capacitance * kVolts);
}

// ---- 2., 3. the free and the blocked bar ---------------------------------------------------------------

struct Bar {
  static constexpr double side = 2e-3, height = 1e-3;
  PiezoMaterialPreset material = piezo_material("PZT-5H");
  Eigen::MatrixXd s = material.c.inverse();  // compliance s^E
  Eigen::MatrixXd d = material.e * s;        // d = e s^E, 3 x 6 [C/N]

  // A box poled along z, driven on zmax, grounded on zmin, on rollers on xmin, ymin, zmin (free to strain
  // uniformly); `blocked`: a roller on zmax too.
  PiezoContactModel build(bool blocked) const {
    const PiezoTensors t = material.tensors(3, Axis::z);
    PiezoContactSpec spec;
    spec.mesh = std::make_shared<const Mesh>(box_mesh({0, 0, 0}, {side, side, height}, 2, 2, 2, Shape::Tetrahedron));
    spec.B = t.B;
    spec.E = t.E;
    spec.beta = t.beta;
    spec.grounded = {"zmin"};
    spec.electrodes = {{"drive", "zmax", TimeFunction::constant(kVolts)}};
    spec.extra_bricks = [blocked](Model& m) {
      m.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("v", "xmin", {0})));
      m.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("v", "ymin", {1})));
      m.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("v", "zmin", {2})));
      if (blocked) m.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("v", "zmax", {2})));
    };
    return build_piezo_contact_model(spec);
  }
};

TEST(DeviceClosedForms, FreeBarStrokesByD33TimesVoltageAndHoldsFreePermittivityCharge) {
  const Bar bar;
  // The preset's constants reproduce the datasheet's d33 of PZT-5H (593 pC/N) to its rounding.
  EXPECT_NEAR(bar.d(2, 2), 593e-12, 0.03 * 593e-12);
  PiezoContactModel built = bar.build(false);
  run(built, 1, 1);
  const Model& m = *built.model;
  // Field E_z = -V / h (against the poling): the bar contracts by d33 V and widens by d31 V side / h.
  const FESpace& space = m.space("v");
  const int top = space.scalar_dofs_on("zmax").front(), corner_x = space.scalar_dofs_on("xmax").back();
  EXPECT_NEAR(m.values("u")[space.dof(top, 2)], -bar.d(2, 2) * kVolts, 1e-9 * bar.d(2, 2) * kVolts);
  const double strain_xx = bar.d(2, 0) * (-kVolts / Bar::height);
  EXPECT_NEAR(m.values("u")[space.dof(corner_x, 0)], strain_xx * Bar::side, 1e-9 * std::abs(strain_xx) * Bar::side);
  // eps^T = eps^S + e d^T: the free body's larger capacitance.
  const double eps_free = bar.material.eps(2, 2) + (bar.material.e * bar.d.transpose())(2, 2);
  const double area = Bar::side * Bar::side;
  EXPECT_GT(eps_free, 1.5 * bar.material.eps(2, 2));
  EXPECT_NEAR(electrode_charge(m, "zmax"), eps_free * area * kVolts / Bar::height,
              1e-9 * eps_free * area * kVolts / Bar::height);
}

TEST(DeviceClosedForms, BlockedBarPushesWithTheBlockedForce) {
  const Bar bar;
  PiezoContactModel built = bar.build(true);
  run(built, 1, 1);
  const Model& m = *built.model;
  // Uniaxial stress with eps_zz = 0: s33 sigma_zz + d33 E_z = 0.
  const double sigma_zz = bar.d(2, 2) * kVolts / (Bar::height * bar.s(2, 2));
  const double force = sigma_zz * Bar::side * Bar::side;
  EXPECT_NEAR(reaction(m, "v", "zmax", 2), force, 1e-9 * std::abs(force));
  EXPECT_NEAR(reaction(m, "v", "zmin", 2), -force, 1e-9 * std::abs(force));
}

// ---- 4., 5. the moving foundation ------------------------------------------------------------------------

constexpr double kLength = 1, kHeight = 0.2, kMu = 0.3;

PiezoContactSpec mechanical_block() {
  PiezoContactSpec spec;
  spec.mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {kLength, kHeight}, 8, 2));
  spec.B = isotropic_stiffness_from_young(2, 1e9, 0.3);
  spec.contact = "bottom";
  return spec;
}

std::shared_ptr<FoundationMotion> moving(TimeFunction along, TimeFunction into) {
  auto motion = std::make_shared<FoundationMotion>();
  motion->velocity[0] = along;
  motion->velocity[1] = into;
  return motion;
}

TEST(DeviceClosedForms, ClampedBodyFeelsTheGapAndTheSlipOfAMovingFoundation) {
  const double c_nu = 1e10, eps = 1e-3, v_along = 0.02, v_into = 1e-4, end = 0.5;
  PiezoContactSpec spec = mechanical_block();
  spec.clamped = {"left", "right", "top", "bottom"};
  spec.normal = {"normal_compliance", {{"c_nu", c_nu}}};
  spec.friction = {"coulomb", {{"mu", kMu}, {"eps", eps}}};
  // Along the surface at a constant speed, into it along a table: 0 until 0.1 s, v_into after 0.2 s.
  spec.foundation_motion = moving(TimeFunction::constant(v_along), TimeFunction::table({{0.1, 0}, {0.2, v_into}}));
  PiezoContactModel built = build_piezo_contact_model(spec);
  EXPECT_TRUE(built.normal->time_dependent());
  int checked = 0;
  run(built, end, 5, [&](const Model& m) {
    const double t = m.time();
    // U_f,y = the table's integral: 0 up to 0.1, the ramp's area, then v_into per second.
    const double rise = t <= 0.1   ? 0
                        : t <= 0.2 ? v_into * (t - 0.1) * (t - 0.1) / (2 * 0.1)
                                   : v_into * (0.05 + t - 0.2);
    const double p = c_nu * rise;  // the body does not move: all of the foundation's rise is overlap
    const double friction = kMu * p * v_along / std::sqrt(v_along * v_along + eps * eps);
    const double scale = c_nu * v_into * end * kLength;
    EXPECT_NEAR(reaction(m, "v", "bottom", 1), -p * kLength, 1e-12 * scale) << "t = " << t;
    EXPECT_NEAR(reaction(m, "v", "bottom", 0), -friction * kLength, 1e-12 * scale) << "t = " << t;
    for (double pressure :
         pressure_at_contact_nodes(*built.normal, m.space("v"), built.contact_nodes, m.values("u"), t))
      EXPECT_NEAR(pressure, p, 1e-12 * scale);
    ++checked;
  });
  EXPECT_EQ(checked, 5);
}

TEST(DeviceClosedForms, DampedNormalLawReadsTheRateRelativeToTheFoundation) {
  const double c_nu = 1e6, v_into = 1e-3;
  PiezoContactSpec spec = mechanical_block();
  spec.clamped = {"left", "right", "top", "bottom"};
  spec.normal = {"linear_damped", {{"c_nu", c_nu}}};
  spec.foundation_motion = moving(TimeFunction::constant(0), TimeFunction::sine(v_into, 1, 0, v_into));
  PiezoContactModel built = build_piezo_contact_model(spec);
  run(built, 1, 4, [&](const Model& m) {
    const double rate = v_into * (1 + std::sin(2 * 3.14159265358979323846 * m.time()));
    EXPECT_NEAR(reaction(m, "v", "bottom", 1), -c_nu * rate * kLength, 1e-12 * c_nu * v_into) << "t = " << m.time();
  });
}

TEST(DeviceClosedForms, BlockPressedOnAMovingFoundationFeelsMuP) {
  // A compliant foundation, so that the block comes to rest on it: on a damped one it would keep sinking,
  // and the couple of the drag and the holder would tilt it at a steady rate, adding to the slip.
  const double pressure = 1e5, c_nu = 1e12, v_along = 0.05;
  for (double eps : {5e-3, 5e-8}) {
    PiezoContactSpec spec = mechanical_block();
    spec.normal = {"normal_compliance", {{"c_nu", c_nu}}};
    spec.friction = {"coulomb", {{"mu", kMu}, {"eps", eps}}};
    spec.tractions = {
        {"top", [=](const double*, double, double* out) { out[0] = 0, out[1] = -pressure; }, LoadTime::Constant}};
    spec.foundation_motion = moving(TimeFunction::constant(v_along), TimeFunction::constant(0));
    // Held by its top along x: the holder's reaction is the friction the foundation drags it with.
    spec.extra_bricks = [](Model& m) {
      m.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("v", "top", {0})));
    };
    PiezoContactModel built = build_piezo_contact_model(spec);
    std::vector<double> holder;
    ContactResultant resultant;
    run(built, 2e-2, 8, [&](const Model& m) {
      holder.push_back(reaction(m, "v", "top", 0));
      resultant = contact_resultant(built);
    });
    // Once the block's shear has settled (its change shrinks a thousandfold per step) it stands still
    // along x, so the slip is the foundation's: the drag is mu p L V / sqrt(V^2 + eps^2), which is mu p L
    // as eps / V -> 0.
    const double drag = kMu * pressure * kLength * v_along / std::sqrt(v_along * v_along + eps * eps);
    for (size_t n = 6; n < holder.size(); ++n)
      EXPECT_NEAR(holder[n], -drag, 1e-9 * drag) << "eps " << eps << " step " << n;
    // The foundation's resultant on the block: the drag along its motion, the pressure's force up.
    EXPECT_NEAR(resultant.force[0], drag, 1e-9 * drag);
    EXPECT_NEAR(resultant.force[1], pressure * kLength, 1e-9 * pressure * kLength);
    if (eps < 1e-6) {
      EXPECT_NEAR(holder.back(), -kMu * pressure * kLength, 1e-9 * drag);
    }
  }
}

}  // namespace
}  // namespace pc
