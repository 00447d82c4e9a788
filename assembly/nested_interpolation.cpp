#include "assembly/nested_interpolation.hpp"

#include <vector>

#include "assembly/cell_geometry.hpp"
#include "assembly/error.hpp"

namespace pc {

Eigen::VectorXd interpolate_nested(const FESpace& coarse, const Eigen::VectorXd& coefficients, const FESpace& fine,
                                   std::span<const int> parent_cell) {
  require(coarse.num_components() == fine.num_components(), "nested interpolation: the coarse space has ",
          coarse.num_components(), " components, the fine one ", fine.num_components());
  require(int(parent_cell.size()) == fine.mesh().num_cells(), "nested interpolation: ", parent_cell.size(),
          " parent cells for a fine mesh of ", fine.mesh().num_cells(), " cells");
  require(coefficients.size() == coarse.num_dofs(), "nested interpolation: ", coefficients.size(),
          " coefficients, the coarse space has ", coarse.num_dofs(), " dofs");
  const int components = fine.num_components();
  Eigen::VectorXd result = Eigen::VectorXd::Zero(fine.num_dofs());
  std::vector<char> done(fine.num_scalar_dofs(), 0);
  std::vector<double> value(components);
  for (int cell = 0; cell < fine.mesh().num_cells(); ++cell) {
    if (!fine.has_cell(cell)) continue;
    const int parent = parent_cell[cell];
    require(parent >= 0 && parent < coarse.mesh().num_cells() && coarse.has_cell(parent),
            "nested interpolation: fine cell ", cell, " lies in coarse cell ", parent,
            ", which is not in the coarse space");
    for (int dof : fine.cell_scalar_dofs(cell)) {
      if (done[dof]) continue;
      done[dof] = 1;
      const auto x = fine.scalar_dof_point(dof);
      double xi[3] = {0, 0, 0};
      require(map_to_reference(coarse.mesh(), parent, x.data(), xi), "nested interpolation: the node of fine dof ", dof,
              " is not found in its parent cell ", parent);
      coarse.evaluate_in_cell(coefficients, parent, xi, value.data());
      for (int c = 0; c < components; ++c) result[fine.dof(dof, c)] = value[c];
    }
  }
  return result;
}

}  // namespace pc
