// A device's scene keys, as a user meets them: electrodes (phi = V(t) on a face region, with time
// functions) and contact.foundation_velocity are read into the spec, refused with the offending path when
// wrong, and a run writes each electrode's V, Q and I into history.csv, continuing them (and the energy
// books) across --resume.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "models/scene/scene.hpp"
#include "models/scene/scene_runner.hpp"
#include "support/csv_table.hpp"
#include "support/error_and_temp_dir.hpp"
#include "support/shipped_scenes.hpp"
#include "support/test_helpers.hpp"
#include "support/vtu_reader.hpp"

namespace pc {
namespace {

using testing::expect_error_containing;

const std::string& kPaper = testing::kPaperScene;
const std::string kSineElectrode =
    R"(electrodes=[{"name": "drive", "region": "right", "voltage": {"type": "sine", "amplitude": 10, "frequency": 50}}])";

Scene coarse(std::vector<std::string> overrides) {
  overrides.insert(overrides.begin(), {"mesh.nx=6", "mesh.ny=2", "time.steps=4"});
  return load_scene_file(kPaper, overrides);
}

TEST(DeviceSceneKeys, ElectrodesAndFoundationVelocityAreRead) {
  const Scene scene = coarse(
      {kSineElectrode, R"(contact.foundation_velocity=[0.25, {"type": "ramp", "value": -1e-3, "duration": 0.1}])"});
  ASSERT_EQ(scene.spec.electrodes.size(), 1u);
  EXPECT_EQ(scene.spec.electrodes[0].region, "right");
  EXPECT_NEAR(scene.spec.electrodes[0].voltage.value(1.0 / 200), 10, 1e-12);
  ASSERT_TRUE(scene.spec.foundation_motion);
  EXPECT_EQ(scene.spec.foundation_motion->velocity[0].value(3), 0.25);
  EXPECT_DOUBLE_EQ(scene.spec.foundation_motion->velocity[1].value(0.05), -0.5e-3);
}

TEST(DeviceSceneKeys, BadElectrodesAreRefusedNamingThePath) {
  expect_error_containing(
      [] { coarse({R"(electrodes=[{"name": "a", "region": "right", "voltage": {"type": "square"}}])"}); },
      {"'electrodes[0].voltage.type' must be constant, ramp, sine or table, got 'square'"});
  expect_error_containing(
      [] {
        coarse(
            {R"(electrodes=[{"name": "a", "region": "right", "voltage": {"type": "sine", "amplitude": 1, "frequency": 0}}])"});
      },
      {"'electrodes[0].voltage.frequency' must be > 0, got 0"});
  expect_error_containing([] { coarse({R"(electrodes=[{"name": "a", "region": "nowhere", "voltage": 1}])"}); },
                          {"electrodes[0].region", "nowhere"});
  expect_error_containing([] { coarse({R"(electrodes=[{"name": "a", "region": "top", "voltage": 1}])"}); },
                          {"'electrodes[0].region': 'top' is grounded"});
  expect_error_containing(
      [] {
        coarse(
            {R"(electrodes=[{"name": "a", "region": "left", "voltage": 1}, {"name": "a", "region": "right", "voltage": 2}])"});
      },
      {"'electrodes[1].name': electrode 'a' is named twice"});
  expect_error_containing(
      [] {
        coarse(
            {R"(electrodes=[{"name": "a", "region": "right", "voltage": {"type": "table", "points": [[0, 1], [0, 2]]}}])"});
      },
      {"'electrodes[0].voltage'", "table times must increase"});
  expect_error_containing(
      [] { coarse({R"(electrodes=[{"name": "a", "region": "right", "voltage": 1, "volts": 2}])"}); },
      {"electrodes[0]", "volts"});
}

TEST(DeviceSceneKeys, FloatingElectrodesAreReadAndAVoltageOrAChargeInTheWrongPlaceRefused) {
  const Scene scene = coarse({R"(electrodes=[{"name": "sense", "region": "left", "floating": true},
                                             {"name": "store", "region": "right", "floating": true, "charge": {"type": "ramp", "value": 1e-9, "duration": 1}}])"});
  ASSERT_EQ(scene.spec.electrodes.size(), 2u);
  EXPECT_EQ(scene.spec.electrodes[0].circuit, ElectrodeCircuit::Floating);
  EXPECT_EQ(scene.spec.electrodes[0].charge.value(0.5), 0.0);
  EXPECT_NEAR(scene.spec.electrodes[1].charge.value(0.5), 0.5e-9, 1e-24);
  expect_error_containing(
      [] { coarse({R"(electrodes=[{"name": "a", "region": "right", "floating": true, "voltage": 1}])"}); },
      {"'electrodes[0]'", "floating electrode's voltage is computed"});
  expect_error_containing(
      [] { coarse({R"(electrodes=[{"name": "a", "region": "right", "voltage": 1, "charge": 1}])"}); },
      {"'electrodes[0]'", "'charge' is for a floating one"});
  expect_error_containing([] { coarse({R"(electrodes=[{"name": "a", "region": "right", "floating": 1}])"}); },
                          {"electrodes[0].floating"});
}

TEST(DeviceSceneKeys, BadFoundationVelocityIsRefusedNamingThePath) {
  expect_error_containing([] { coarse({"contact.foundation_velocity=[0.1]"}); },
                          {"'contact.foundation_velocity' must list 2 time functions", "got 1"});
  expect_error_containing(
      [] { coarse({R"(contact.foundation_velocity=[0, {"type": "ramp", "value": 1, "duration": -1}])"}); },
      {"'contact.foundation_velocity[1].duration' must be > 0, got -1"});
  expect_error_containing([] { coarse({R"(contact.foundation_velocity=[0, "fast"])"}); },
                          {"'contact.foundation_velocity[1]' must be a number or a time function"});
}

class DeviceSceneRun : public testing::TemporaryDirectoryTest {};

// The electrode's columns: V is the sine, Q the reaction, I its backward difference; a resumed run's
// rows are the uninterrupted run's, I included (its previous charge comes back from the checkpoint).
TEST_F(DeviceSceneRun, HistoryHoldsEachElectrodesVoltageChargeAndCurrentAcrossAResume) {
  const Scene scene = coarse({kSineElectrode, "output.checkpoint_every=1", "time.steps=6"});
  const SceneFoundation& foundation = find_foundation(scene, "insulated");
  const auto whole_dir = directory_ / "whole", part_dir = directory_ / "part";
  ASSERT_TRUE(run_foundation(scene, foundation, whole_dir.string(), false).completed);
  const testing::Table whole = testing::read_csv(whole_dir / "history.csv");
  const int v = whole.column("V_drive"), q = whole.column("Q_drive"), i = whole.column("I_drive");
  ASSERT_EQ(whole.rows.size(), 6u);
  double previous_q = 0, previous_t = 0;
  for (const auto& row : whole.rows) {
    EXPECT_NEAR(row[v], 10 * std::sin(2 * std::numbers::pi * 50 * row[0]), 1e-9);
    EXPECT_NE(row[q], 0.0);
    EXPECT_NEAR(row[i], (row[q] - previous_q) / (row[0] - previous_t), 1e-6 * std::abs(row[i]) + 1e-300);
    previous_q = row[q];
    previous_t = row[0];
  }

  // Stopped by its budget after 3 step attempts, then resumed: the rows after the stop are the same numbers.
  const Scene budget = coarse({kSineElectrode, "output.checkpoint_every=1", "time.steps=6", "time.max_attempts=3"});
  EXPECT_FALSE(run_foundation(budget, find_foundation(budget, "insulated"), part_dir.string(), false).completed);
  FoundationRunOptions resuming;
  resuming.directory = part_dir.string();
  resuming.progress = false;
  resuming.resume = true;
  FoundationRun second(scene, foundation);
  ASSERT_TRUE(second.run(resuming).completed);
  const testing::Table resumed = testing::read_csv(part_dir / "history.csv");
  ASSERT_EQ(resumed.rows.size(), whole.rows.size());
  // Every column, the electrodes' and the energy books' included, to the last digit.
  ASSERT_EQ(resumed.columns, whole.columns);
  for (size_t n = 0; n < whole.rows.size(); ++n)
    for (size_t c = 0; c < whole.columns.size(); ++c)
      EXPECT_EQ(resumed.rows[n][c], whole.rows[n][c]) << whole.columns[c] << " at row " << n;
}

// A floating electrode's columns: Q is the given charge, V the potential the run computes; the energy
// books still balance (the charge enters as a source on the electrode). One touching a grounded region
// is refused naming both.
TEST_F(DeviceSceneRun, FloatingElectrodeReportsItsComputedVoltageAndGivenCharge) {
  // On the contact face: it shares no dof with the grounded top (left and right would, at the corners).
  const Scene scene = coarse(
      {R"(electrodes=[{"name": "sense", "region": "bottom", "floating": true, "charge": {"type": "ramp", "value": 1e-9, "duration": 0.1}}])"});
  ASSERT_TRUE(run_foundation(scene, find_foundation(scene, "insulated"), directory_.string(), false).completed);
  const testing::Table history = testing::read_csv(directory_ / "history.csv");
  const int v = history.column("V_sense"), q = history.column("Q_sense"), balance = history.column("E_balance");
  const int work = history.column("W_external");
  double previous_v = 0;
  for (const auto& row : history.rows) {
    EXPECT_NEAR(row[q], 1e-9 * std::min(row[0] / 0.1, 1.0), 1e-21);
    EXPECT_NE(row[v], previous_v) << "the floating potential follows its charge";
    previous_v = row[v];
    EXPECT_LT(std::abs(row[balance]), 1e-8 * std::abs(row[work]) + 1e-300) << "at t = " << row[0];
  }
  const Scene corner = coarse({R"(electrodes=[{"name": "sense", "region": "left", "floating": true}])"});
  expect_error_containing([&] { FoundationRun run(corner, find_foundation(corner, "insulated")); },
                          {"region 'left' shares dofs of 'phi' with a Dirichlet condition"});
}

// contact_state in the VTU files: 0 where the node is not pressed, else 1 (sticking) or 2 (slipping); the
// slip is relative to the foundation, so a foundation sliding at 1 m/s under the strip makes every pressed
// node slip, and the same strip on a foundation at rest (slipping at ~1e-10 m/s) has sticking nodes
// under a threshold of 1 mm/s.
TEST_F(DeviceSceneRun, ContactStateIsSlipRelativeToTheFoundation) {
  auto final_states = [&](const std::string& name, std::vector<std::string> overrides) {
    overrides.insert(overrides.end(), {"output.vtu_every=4", "output.slip_threshold=1e-3"});
    const Scene scene = coarse(overrides);
    const auto dir = directory_ / name;
    EXPECT_TRUE(run_foundation(scene, find_foundation(scene, "insulated"), dir.string(), false).completed);
    const std::string vtu = testing::read_text(dir / "paper2d_000004.vtu");
    const auto pressure = testing::find_array(vtu, "PointData", "contact_pressure").doubles();
    const auto state = testing::find_array(vtu, "PointData", "contact_state").doubles();
    EXPECT_EQ(state.size(), pressure.size());
    std::map<double, int> count;
    for (size_t n = 0; n < state.size(); ++n) {
      EXPECT_EQ(state[n] == 0, !(pressure[n] > 0)) << "node " << n;
      ++count[state[n]];
    }
    return count;
  };
  const auto moving = final_states("moving", {"contact.foundation_velocity=[1, 0]"});
  EXPECT_GT(moving.count(2.0) ? moving.at(2.0) : 0, 0);
  EXPECT_EQ(moving.count(1.0), 0u);
  const auto at_rest = final_states("at_rest", {});
  EXPECT_GT(at_rest.count(1.0) ? at_rest.at(1.0) : 0, 0);
  EXPECT_EQ(at_rest.count(2.0), 0u);
}

}  // namespace
}  // namespace pc
