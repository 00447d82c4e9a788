#include "assembly/block_pattern.hpp"

#include <algorithm>

namespace pc {

void element_dofs(const FESpace& space, const RegionGeometry& geometry, int element, std::vector<int>& dofs) {
  const auto cell_dofs = space.cell_scalar_dofs(geometry.cell(element));
  const int face = geometry.local_face(element);
  const int nc = space.num_components();
  auto add = [&](int local, int position) {
    for (int c = 0; c < nc; ++c) dofs[position * nc + c] = space.dof(cell_dofs[local], c);
  };
  if (face < 0) {
    dofs.resize(cell_dofs.size() * nc);
    for (int i = 0; i < int(cell_dofs.size()); ++i) add(i, i);
  } else {
    const auto on_face = space.element().face_dofs(face);
    dofs.resize(on_face.size() * nc);
    for (int i = 0; i < int(on_face.size()); ++i) add(on_face[i], i);
  }
}

BlockPattern make_block_pattern(const RegionGeometry& geometry, const FESpace& test, const FESpace& trial) {
  BlockPattern p;
  std::vector<int> rows, cols;
  std::vector<Eigen::Triplet<double, int>> entries;
  for (int e = 0; e < geometry.num_elements(); ++e) {
    element_dofs(test, geometry, e, rows);
    element_dofs(trial, geometry, e, cols);
    for (int r : rows)
      for (int c : cols) entries.emplace_back(r, c, 0.0);
  }
  CsrMatrix matrix(test.num_dofs(), trial.num_dofs());
  matrix.setFromTriplets(entries.begin(), entries.end());
  matrix.makeCompressed();
  p.rows = int(matrix.rows());
  p.cols = int(matrix.cols());
  p.outer.assign(matrix.outerIndexPtr(), matrix.outerIndexPtr() + matrix.rows() + 1);
  p.inner.assign(matrix.innerIndexPtr(), matrix.innerIndexPtr() + matrix.nonZeros());
  return p;
}

}  // namespace pc
