#pragma once
// What a run will take, predicted from its size before it starts, so that a user sees a long run coming
// (the progress lines replace it by the measured rate once steps are done). A cost model fitted to whole
// runs of the shipped scenes on the 2-core reference machine (benchmarks/cost_growth_study, release
// build, conductive foundation, about 2 Newton iterations a step):
//   2D, P1: 4.8 ms a step at 3.8k dofs, 18 ms at 15k, 105 ms at 59k      -> 4.8 ms * (n / 3843)^1.15
//   3D, P1: 9.5 ms a step at 2.3k dofs, 115 ms at 8.4k                    -> 9.5 ms * (n / 2308)^1.95
// Past the condensed solve's cap on contact dofs (solver.condensed_max_dofs) every Newton iteration
// factorises in full, and 3D runs grow faster still (24k dofs: 7 s a step, 7 times the model's figure):
// the prediction is an order of magnitude, not a promise.
namespace pc {

class Model;

struct TimeEstimate {
  double seconds = 0;
  const char* basis = "";  // what the figure rests on, for the message
};

TimeEstimate estimate_run_seconds(int dim, double dofs, int steps);
// The dofs of all the model's unknowns: what a run's size is counted in.
int model_dofs(const Model& model);
// A run of `steps` steps of the model, from its dimension and model_dofs: what `piezocontact check`
// and a run's first progress line predict, from this one function.
TimeEstimate estimate_run_seconds(const Model& model, int steps);

}  // namespace pc
