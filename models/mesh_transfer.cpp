#include "models/mesh_transfer.hpp"

#include "assembly/error.hpp"
#include "assembly/nested_interpolation.hpp"

namespace pc {

void transfer_model_state(const Model& from, const TimeScheme& from_scheme, Model& to, TimeScheme& to_scheme,
                          std::span<const int> parent_cell) {
  require(from.field_names() == to.field_names(), "mesh transfer: the models have different fields");
  require(from_scheme.name() == to_scheme.name(), "mesh transfer: the time schemes differ ('", from_scheme.name(),
          "' and '", to_scheme.name(), "')");
  std::map<std::string, Eigen::VectorXd> values;
  for (const std::string& name : to.field_names()) {
    require(from.field_kind(name) == to.field_kind(name), "mesh transfer: the field '", name, "' is of another kind");
    if (to.field_kind(name) == FieldKind::Affine) continue;
    values[name] = interpolate_nested(from.space(name), from.values(name), to.space(name), parent_cell);
  }
  for (const std::string& name : to.field_names()) {
    if (to.field_kind(name) == FieldKind::Affine)
      to.set_affine(name, from.affine_factor(name), from.affine_coefficients(name));
    else
      to.set_values(name, values.at(name));
  }
  to.set_time(from.time());
  to_scheme.restore_history_state(from_scheme.history_state());
}

}  // namespace pc
