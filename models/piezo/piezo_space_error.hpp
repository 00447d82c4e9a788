#pragma once
// The spatial error estimate of a piezoelectric body (models/space_error_estimate.hpp), field by field in
// the norm of its own energy:
//   u    strain in the elasticity B        (1/2 eps:B eps, the stored elastic energy)
//   v    strain rate in the viscosity A    (the viscous power), when the model has A
//   phi  gradient in the permittivity beta (the stored electric energy)
// The coupling E is left out of the norms: it is indefinite, and each block's own energy already weighs
// the field's gradient. A field the model does not have is left out, as is one whose constant is missing.
#include "models/model.hpp"
#include "models/output/piezo_fields.hpp"
#include "models/space_error_estimate.hpp"

namespace pc {

SpaceErrorEstimate piezo_space_error(const Model& model, const PiezoFieldNames& names = {});

}  // namespace pc
