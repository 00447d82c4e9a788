#pragma once
// The cells of a mesh split into parts of nearly equal size with few faces between them, for the
// processes of a distributed run: METIS's k-way partition of the cells' dual graph (cells adjacent
// through a face). Deterministic: the same mesh gives the same parts on every process.
#include <vector>

#include "assembly/mesh.hpp"

namespace pc {

// owner[c] in [0, parts): the part of cell c. One part: all zeros, without METIS.
std::vector<int> partition_cells(const Mesh& mesh, int parts);

// owned[c] = 1 where owner[c] == part.
std::vector<char> cells_of_part(const std::vector<int>& owner, int part);

}  // namespace pc
