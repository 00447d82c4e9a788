#include "models/piezo/piezo_space_error.hpp"

namespace pc {

SpaceErrorEstimate PiezoSpaceErrorEstimator::operator()(const Model& model) {
  SpaceErrorEstimate estimate;
  const auto add = [&](const std::string& field, const char* constant, GradientMeasure measure) {
    if (!model.has_field(field) || !model.has_constant(constant)) return;
    const FESpace& space = model.space(field);
    const SpaceErrorEstimator*& estimator = serving_[&space];
    for (const auto& candidate : estimators_)
      if (!estimator && candidate->serves(space)) estimator = candidate.get();
    if (!estimator) estimator = estimators_.emplace_back(std::make_unique<SpaceErrorEstimator>(space)).get();
    estimate.fields.push_back(
        estimator->estimate(field, space, model.values(field), measure, model.constant(constant)));
  };
  add(names_.displacement, "B", GradientMeasure::Strain);
  add(names_.velocity, "A", GradientMeasure::Strain);
  add(names_.potential, "beta", GradientMeasure::Gradient);
  return estimate;
}

SpaceErrorEstimate piezo_space_error(const Model& model, const PiezoFieldNames& names) {
  return PiezoSpaceErrorEstimator(names)(model);
}

}  // namespace pc
