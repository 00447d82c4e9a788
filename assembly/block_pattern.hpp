#pragma once
// The sparsity pattern of a tangent block between two FE spaces over a region (rows: dofs of the test
// space, columns: dofs of the trial space): the union of the elements' local blocks. It depends on the
// region's elements and the two spaces only: terms over the same region and spaces (elasticity, viscosity
// and inertia on the body's velocity) share one (assembly/term_assembly_cache.hpp).
#include <vector>

#include "assembly/fe_space.hpp"
#include "assembly/region_geometry.hpp"
#include "assembly/sparse.hpp"

namespace pc {

struct BlockPattern {
  int rows = 0, cols = 0;
  std::vector<int> outer, inner;  // the CSR pattern (no values: each term's block has its own)
};

// The dofs of a space an element of the region touches: all of its cell's (cells), or those on its
// face (faces), each scalar dof's components together.
void element_dofs(const FESpace& space, const RegionGeometry& geometry, int element, std::vector<int>& dofs);

BlockPattern make_block_pattern(const RegionGeometry& geometry, const FESpace& test, const FESpace& trial);

}  // namespace pc
