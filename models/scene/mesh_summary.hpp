#pragma once
// The "mesh" object of a run's summary.json: what the mesh is and where it came from.
//   description                  the runner's one line ("60 x 20 triangles", "gmsh 'box3d.geo': 3107 tetrahedrons")
//   source                       "generated" or "gmsh"
//   generator, nx, ny (nz), h    a generated mesh: mesh.generator, cells along each axis, cell size along each axis
//   file, size_factor            a gmsh mesh: mesh.gmsh as the scene gives it, mesh.size_factor
//   dim, nodes, cells, cell_type, h_min, h_max   every mesh: h_min and h_max are its shortest and longest edge
#include "models/scene/json.hpp"
#include "models/scene/scene.hpp"

namespace pc {

Json mesh_summary(const Scene& scene);

}  // namespace pc
