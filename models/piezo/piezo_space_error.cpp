#include "models/piezo/piezo_space_error.hpp"

namespace pc {

SpaceErrorEstimate piezo_space_error(const Model& model, const PiezoFieldNames& names) {
  SpaceErrorEstimate estimate;
  const auto add = [&](const std::string& field, const char* constant, GradientMeasure measure) {
    if (!model.has_field(field) || !model.has_constant(constant)) return;
    estimate.fields.push_back(
        recovery_error_estimate(field, model.space(field), model.values(field), measure, model.constant(constant)));
  };
  add(names.displacement, "B", GradientMeasure::Strain);
  add(names.velocity, "A", GradientMeasure::Strain);
  add(names.potential, "beta", GradientMeasure::Gradient);
  return estimate;
}

}  // namespace pc
