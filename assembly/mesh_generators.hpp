#pragma once
// Structured meshes of a rectangle and of a box. Sides become face regions named by where they lie:
// "xmin", "xmax", "ymin", "ymax" (and "zmin", "zmax" in 3D), with the aliases "left", "right",
// "bottom", "top" in 2D. The cell region "all" covers the domain.
#include <array>

#include "assembly/mesh.hpp"

namespace pc {

// nx * ny cells of shape Triangle (each rectangle split along its diagonal) or Quadrilateral.
Mesh rectangle_mesh(std::array<double, 2> lower, std::array<double, 2> upper, int nx, int ny,
                    Shape shape = Shape::Triangle);

// nx * ny * nz cells of shape Tetrahedron (each hexahedron split into six, conforming) or Hexahedron.
Mesh box_mesh(std::array<double, 3> lower, std::array<double, 3> upper, int nx, int ny, int nz,
              Shape shape = Shape::Tetrahedron);

}  // namespace pc
