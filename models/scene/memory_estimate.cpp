#include "models/scene/memory_estimate.hpp"

#include <sys/resource.h>

#include <algorithm>
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

namespace {

// A number from the first line of a file ("max" or no file: nothing).
double number_in(const char* path) {
  std::ifstream in(path);
  double value = 0;
  return in >> value ? value : 0;
}

}  // namespace

double available_memory_bytes() {
  double bytes = 0;
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string key;
    double kib = 0;
    if (fields >> key >> kib && key == "MemAvailable:") bytes = kib * 1024;
  }
  auto at_most = [&](double limit) {
    if (limit > 0) bytes = bytes > 0 ? std::min(bytes, limit) : limit;
  };
  // What this process may use can be less than the machine has: its address-space limit (ulimit -v) and
  // its cgroup's memory.max (a container, a batch job).
  rlimit address_space{};
  if (getrlimit(RLIMIT_AS, &address_space) == 0 && address_space.rlim_cur != RLIM_INFINITY)
    at_most(double(address_space.rlim_cur));
  if (const double max = number_in("/sys/fs/cgroup/memory.max"); max > 0)
    at_most(max - number_in("/sys/fs/cgroup/memory.current"));
  return bytes;
}

}  // namespace pc
