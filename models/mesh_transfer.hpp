#pragma once
// Moving a run to a refined mesh mid-way: the same model, built on a mesh that refines the model's own
// (assembly/mesh_bisection.hpp), takes over its state: every unknown and data field (the history fields
// u_prev, v_prev, ... with them) by nested interpolation, exact for Lagrange spaces of one order; the
// affine fields' maps, the model's time and the scheme's history as they are. The run goes on from there
// on the new mesh; what the old mesh had not resolved stays unresolved until the new one's steps do.
#include <span>

#include "models/model.hpp"
#include "models/time_scheme.hpp"

namespace pc {

// parent_cell: for each cell of `to`'s mesh, the cell of `from`'s it lies in. Throws, before anything is
// changed, if the models' fields differ in name, kind or components, or if the schemes differ.
void transfer_model_state(const Model& from, const TimeScheme& from_scheme, Model& to, TimeScheme& to_scheme,
                          std::span<const int> parent_cell);

}  // namespace pc
