#pragma once
// What a run's summary says about its mesh: its size and the range of its edge lengths.
#include "assembly/mesh.hpp"

namespace pc {

struct MeshStatistics {
  int dim = 0, nodes = 0, cells = 0;
  Shape cell_shape = Shape::Point;
  double h_min = 0, h_max = 0;  // the shortest and the longest edge of any cell
};

MeshStatistics mesh_statistics(const Mesh& mesh);

}  // namespace pc
