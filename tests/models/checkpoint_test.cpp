// Checkpoints and resumed runs: a checkpoint reads back bit for bit and a damaged one is refused; a run
// stopped part-way and continued from its checkpoint, in a model built anew (as a new process would),
// ends with exactly the state of the uninterrupted run, for each time scheme (BDF2 and theta keep state
// beyond the model's fields: without it the resumed run would differ).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>

#include "models/model_state.hpp"
#include "models/output/checkpoint.hpp"
#include "models/scene/scene.hpp"
#include "support/error_and_temp_dir.hpp"
#include "support/test_helpers.hpp"

namespace pc {
namespace {

using testing::error_of;

class CheckpointFile : public testing::TemporaryDirectoryTest {};

TEST_F(CheckpointFile, ReadsBackBitForBit) {
  Checkpoint c;
  c.numbers["tiny"] = std::numeric_limits<double>::denorm_min();
  c.numbers["minus_zero"] = -0.0;
  c.numbers["tenth"] = 0.1;
  c.vectors["v"] = Eigen::VectorXd::LinSpaced(1001, -1.0 / 3.0, 1e300);
  c.vectors["empty"] = Eigen::VectorXd();
  c.texts["scheme"] = "bdf2";
  const std::string path = (directory_ / "c.bin").string();
  write_checkpoint(path, c);
  const Checkpoint r = read_checkpoint(path);
  EXPECT_EQ(r.numbers, c.numbers);
  EXPECT_TRUE(std::signbit(r.number("minus_zero")));
  ASSERT_EQ(r.vector("v").size(), 1001);
  EXPECT_EQ((r.vector("v") - c.vectors["v"]).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(r.vector("empty").size(), 0);
  EXPECT_EQ(r.text("scheme"), "bdf2");
  EXPECT_CONTAINS(error_of([&] { r.number("absent"); }), "no number 'absent'");
}

TEST_F(CheckpointFile, ADamagedTruncatedOrForeignFileIsRefusedNamingIt) {
  Checkpoint c;
  c.vectors["v"] = Eigen::VectorXd::Ones(100);
  const std::string path = (directory_ / "c.bin").string();
  write_checkpoint(path, c);
  std::string bytes = testing::read_text(path);

  bytes[bytes.size() / 2] ^= 0x10;
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  EXPECT_CONTAINS(error_of([&] { read_checkpoint(path); }), "checkpoint '" + path + "' is damaged");

  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes.substr(0, 40);
  EXPECT_CONTAINS(error_of([&] { read_checkpoint(path); }), path);

  std::ofstream(path, std::ios::binary | std::ios::trunc) << "{\"not\": \"a checkpoint\"}";
  EXPECT_CONTAINS(error_of([&] { read_checkpoint(path); }), "is not a piezocontact checkpoint");
  EXPECT_CONTAINS(error_of([&] { read_checkpoint((directory_ / "absent.bin").string()); }), "cannot open");
}

// The paper's strip (coarse), conductive foundation, with the given time scheme.
PiezoContactModel paper_model(const Choice& scheme) {
  const Scene scene = load_scene_file(std::string(PIEZOCONTACT_SCENES) + "/paper2d.json", {"mesh.nx=12", "mesh.ny=4"});
  PiezoContactSpec spec = scene.spec;
  spec.foundation = find_foundation(scene, "conductive").law;
  spec.scheme = scheme;
  return build_piezo_contact_model(spec);
}

StepperOptions twelve_steps() {
  StepperOptions o;
  o.end = 0.012;
  o.step = 0.001;
  return o;
}

class ResumedRun : public ::testing::TestWithParam<Choice> {};

TEST_P(ResumedRun, EndsWithExactlyTheUninterruptedState) {
  NewtonSolver newton;
  PiezoContactModel whole = paper_model(GetParam());
  {
    const RunSummary s = Stepper(twelve_steps()).run(*whole.model, *whole.scheme, newton);
    ASSERT_TRUE(s.completed) << s.message;
  }

  // Stopped after 5 step attempts: the checkpoint callback is given the state at the stop.
  PiezoContactModel first = paper_model(GetParam());
  StepperOptions stopping = twelve_steps();
  stopping.max_attempts = 5;
  Checkpoint checkpoint;
  std::optional<StepperState> stopped_at;
  StepperCallbacks callbacks;
  callbacks.on_checkpoint = [&](const Model& m, const StepperState& state) {
    save_model_state(m, *first.scheme, checkpoint);
    save_stepper_state(state, checkpoint);
    stopped_at = state;
  };
  NewtonSolver first_newton;
  const RunSummary part = Stepper(stopping).run(*first.model, *first.scheme, first_newton, callbacks);
  ASSERT_FALSE(part.completed);
  ASSERT_TRUE(stopped_at.has_value());
  EXPECT_EQ(stopped_at->steps, 5);

  // A model built anew, as a new process would, continues from the checkpoint.
  PiezoContactModel second = paper_model(GetParam());
  restore_model_state(*second.model, *second.scheme, checkpoint);
  StepperOptions resuming = twelve_steps();
  resuming.resume = restore_stepper_state(checkpoint);
  EXPECT_EQ(resuming.resume->step_size, stopped_at->step_size);
  NewtonSolver second_newton;
  const RunSummary rest = Stepper(resuming).run(*second.model, *second.scheme, second_newton);
  ASSERT_TRUE(rest.completed) << rest.message;
  EXPECT_EQ(rest.steps, 12);
  for (const char* field : {"v", "u", "phi"})
    EXPECT_EQ((second.model->values(field) - whole.model->values(field)).cwiseAbs().maxCoeff(), 0.0) << field;
}

INSTANTIATE_TEST_SUITE_P(EachScheme, ResumedRun,
                         ::testing::Values(Choice{"backward_euler", {}}, Choice{"bdf2", {}},
                                           Choice{"theta", {{"theta", 0.5}}}),
                         [](const auto& info) { return info.param.name; });

// An adaptive run stopped part-way, its checkpoint written to disk and read back, continues with the
// same step sizes, rejections and time error estimate as the run that was not stopped: the estimate's
// history (the last solutions, the sum of local errors, the scales) is in the checkpoint.
class ResumedAdaptiveRun : public testing::TemporaryDirectoryTest {};

TEST_F(ResumedAdaptiveRun, ContinuesTheStepsAndTheEstimateExactly) {
  StepperOptions adaptive = twelve_steps();
  adaptive.adaptive = AdaptiveSteps{};
  adaptive.adaptive->tolerance = 1e-3;
  NewtonSolver newton;
  PiezoContactModel whole = paper_model({"bdf2", {}});
  const RunSummary uninterrupted = Stepper(adaptive).run(*whole.model, *whole.scheme, newton);
  ASSERT_TRUE(uninterrupted.completed) << uninterrupted.message;
  ASSERT_GT(uninterrupted.steps, 8) << "the stop below should fall inside the run";

  PiezoContactModel first = paper_model({"bdf2", {}});
  StepperOptions stopping = adaptive;
  stopping.max_attempts = 6;
  const std::string path = (directory_ / "checkpoint.bin").string();
  StepperCallbacks callbacks;
  callbacks.on_checkpoint = [&](const Model& m, const StepperState& state) {
    Checkpoint c;
    save_model_state(m, *first.scheme, c);
    save_stepper_state(state, c);
    write_checkpoint(path, c);
  };
  NewtonSolver first_newton;
  ASSERT_FALSE(Stepper(stopping).run(*first.model, *first.scheme, first_newton, callbacks).completed);

  PiezoContactModel second = paper_model({"bdf2", {}});
  const Checkpoint checkpoint = read_checkpoint(path);
  restore_model_state(*second.model, *second.scheme, checkpoint);
  StepperOptions resuming = adaptive;
  resuming.resume = restore_stepper_state(checkpoint);
  NewtonSolver second_newton;
  const RunSummary rest = Stepper(resuming).run(*second.model, *second.scheme, second_newton);
  ASSERT_TRUE(rest.completed) << rest.message;
  EXPECT_EQ(rest.steps, uninterrupted.steps);
  EXPECT_EQ(rest.rejections, uninterrupted.rejections);
  EXPECT_EQ(rest.state.step_size, uninterrupted.state.step_size);
  ASSERT_EQ(rest.time_error.fields.size(), uninterrupted.time_error.fields.size());
  for (size_t i = 0; i < rest.time_error.fields.size(); ++i) {
    EXPECT_GT(uninterrupted.time_error.fields[i].global, 0) << uninterrupted.time_error.fields[i].field;
    EXPECT_EQ(rest.time_error.fields[i].global, uninterrupted.time_error.fields[i].global)
        << rest.time_error.fields[i].field;
  }
  for (const char* field : {"v", "u", "phi"})
    EXPECT_EQ((second.model->values(field) - whole.model->values(field)).cwiseAbs().maxCoeff(), 0.0) << field;
}

TEST(ModelState, ACheckpointOfAnotherModelIsRefusedAndChangesNothing) {
  PiezoContactModel coarse = paper_model({"backward_euler", {}});
  Checkpoint checkpoint;
  save_model_state(*coarse.model, *coarse.scheme, checkpoint);
  const Scene scene = load_scene_file(std::string(PIEZOCONTACT_SCENES) + "/paper2d.json", {"mesh.nx=6", "mesh.ny=2"});
  PiezoContactSpec spec = scene.spec;
  spec.foundation = find_foundation(scene, "conductive").law;
  PiezoContactModel other = build_piezo_contact_model(spec);
  EXPECT_CONTAINS(error_of([&] { restore_model_state(*other.model, *other.scheme, checkpoint); }),
                  "it is of another mesh or model");
  PiezoContactModel bdf2 = paper_model({"bdf2", {}});
  EXPECT_CONTAINS(error_of([&] { restore_model_state(*bdf2.model, *bdf2.scheme, checkpoint); }),
                  "time scheme 'backward_euler'");
}

}  // namespace
}  // namespace pc
