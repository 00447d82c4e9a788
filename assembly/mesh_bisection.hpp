#pragma once
// Local refinement of a triangle mesh by newest-vertex bisection (Mitchell 1991; Binev, Dahmen and
// DeVore 2004), which keeps the mesh conforming and its angles bounded below however often it is
// applied.
//
// A triangle's vertex 0 is its newest vertex and (1, 2) its refinement edge; bisecting it at the edge's
// midpoint m gives (m, 0, 1) and (m, 2, 0), both counter-clockwise, whose refinement edges are the old
// triangle's other two edges. The marked cells' refinement edges are bisected, and so is, until none is
// left, the refinement edge of every cell with a bisected edge (the conforming closure); a cell is then
// split two, three or four ways. The meshes bisection makes keep the convention, so a mesh can be
// bisected again and again; a first mesh is given its refinement edges by RefinementEdge::Longest.
//
// Regions follow: a child is in its parent's cell regions, and the halves of a face are in the face's
// regions, on the side of the same cell. The new mesh is nested in the old: each new cell lies in one
// old cell, its parent, which is what moves fields from one to the other (nested_interpolation.hpp).
#include <memory>
#include <vector>

#include "assembly/mesh.hpp"

namespace pc {

enum class RefinementEdge {
  OppositeVertexZero,  // a mesh bisection made: vertex 0 is the newest
  Longest,             // a first mesh: each triangle's longest edge (the first of equal ones)
};

struct MeshBisection {
  std::shared_ptr<const Mesh> mesh;
  std::vector<int> parent_cell;  // for each cell of the new mesh, the old cell it lies in
};

// Throws unless the mesh is of triangles in 2D, or if a marked cell does not exist. Marking no cell
// returns a copy of the mesh.
MeshBisection bisect(const Mesh& mesh, const std::vector<int>& marked_cells,
                     RefinementEdge edges = RefinementEdge::OppositeVertexZero);

// Dörfler's marking: the fewest cells, largest indicators first, whose squared indicators sum to at
// least `fraction` (0 < fraction <= 1) of the total. Throws on a fraction outside (0, 1] or a negative
// or non-finite indicator.
std::vector<int> dorfler_marking(const std::vector<double>& indicators, double fraction);

}  // namespace pc
