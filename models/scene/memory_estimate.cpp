#include "models/scene/memory_estimate.hpp"

#include <fstream>
#include <sstream>
#include <string>

namespace pc {

MemoryEstimate estimate_structured_run(int dim, const int* cells, int order) {
  double nodes = 1;
  for (int d = 0; d < dim; ++d) nodes *= double(order) * cells[d] + 1;
  MemoryEstimate e;
  e.dofs = nodes * (dim + 1);  // v and phi
  const double kib_per_dof = dim == 3 ? 32 : (order == 1 ? 8 : 10);
  e.bytes = e.dofs * kib_per_dof * 1024;
  return e;
}

double available_memory_bytes() {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string key;
    double kib = 0;
    if (fields >> key >> kib && key == "MemAvailable:") return kib * 1024;
  }
  return 0;
}

}  // namespace pc
