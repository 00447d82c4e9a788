#pragma once
// The spatial error estimate of a piezoelectric body (models/space_error_estimate.hpp), field by field in
// the norm of its own energy:
//   u    strain in the elasticity B        (1/2 eps:B eps, the stored elastic energy)
//   v    strain rate in the viscosity A    (the viscous power), when the model has A
//   phi  gradient in the permittivity beta (the stored electric energy)
// The coupling E is left out of the norms: it is indefinite, and each block's own energy already weighs
// the field's gradient. A field the model does not have is left out, as is one whose constant is missing.
#include <map>
#include <memory>
#include <vector>

#include "models/model.hpp"
#include "models/output/piezo_fields.hpp"
#include "models/space_error_estimate.hpp"

namespace pc {

// The estimate of a run, which asks it again and again of one model: the estimators are built at the first
// call and kept, one for all the spaces of one scalar structure (SpaceErrorEstimator::serves: the velocity's
// and the potential's P1 spaces share one, 3.5 MB at the paper's 240 x 80). The model's spaces must outlive
// it (a model moved to a new mesh needs a new one).
class PiezoSpaceErrorEstimator {
 public:
  explicit PiezoSpaceErrorEstimator(PiezoFieldNames names = {}) : names_(std::move(names)) {}
  SpaceErrorEstimate operator()(const Model& model);

 private:
  PiezoFieldNames names_;
  std::vector<std::unique_ptr<SpaceErrorEstimator>> estimators_;
  std::map<const FESpace*, const SpaceErrorEstimator*> serving_;  // each space's, once found
};

// Once, for one state.
SpaceErrorEstimate piezo_space_error(const Model& model, const PiezoFieldNames& names = {});

}  // namespace pc
