#include "assembly/threads.hpp"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <string>
#include <thread>

#include <Eigen/Core>

#include "assembly/error.hpp"
#include "assembly/processes.hpp"

namespace pc {
namespace {

std::atomic<int> chosen_threads{0};  // 0: the default

}  // namespace

int default_assembly_threads() {
  if (const char* text = std::getenv("PIEZOCONTACT_THREADS"); text != nullptr && *text != '\0') {
    char* end = nullptr;
    const long threads = std::strtol(text, &end, 10);
    require(*end == '\0' && threads >= 1 && threads <= 4096,
            "PIEZOCONTACT_THREADS must be an integer from 1 to 4096, got '", text, "'");
    return int(threads);
  }
  // The processes of a distributed run share the cores (each one's threads would compete with the others').
  const unsigned cores = std::thread::hardware_concurrency();
  return cores == 0 ? 1 : std::max(1, int(cores) / processes::count());
}

int assembly_threads() {
  const int chosen = chosen_threads.load();
  return chosen > 0 ? chosen : default_assembly_threads();
}

void set_assembly_threads(int threads) {
  require(threads >= 0, "set_assembly_threads: the thread count must be >= 1 (0: the default), got ", threads);
  chosen_threads.store(threads);
  // Eigen's own parallel products (a sparse matrix times a vector: the solvers' residual checks, GMRES)
  // take the same count, so that solver.threads = 1 is one thread, not one plus Eigen's spinning pool.
  Eigen::setNbThreads(assembly_threads());
}

int eigen_product_threads() { return Eigen::nbThreads(); }

}  // namespace pc
