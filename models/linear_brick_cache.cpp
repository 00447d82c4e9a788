#include "models/linear_brick_cache.hpp"

#include <cstddef>

#include "assembly/processes.hpp"

namespace pc {

void LinearBrickCache::invalidate() {
  tangent_valid = false;
  r0_valid = false;
}

bool LinearBrickCache::r0_current(bool time_dependent, double time,
                                  const std::function<std::uint64_t(const std::string&)>& version) const {
  bool current = r0_valid && (!time_dependent || r0_time == time);
  for (const auto& [name, seen] : r0_data_versions) current = current && version(name) == seen;
  return current;
}

void LinearBrickCache::clear_r0() {
  r0.clear();
  r0_data_versions.clear();
}

void LinearBrickCache::finish_r0(double time) {
  r0_zero.clear();
  for (auto& [u, piece] : r0) {
    processes::sum({piece.data(), size_t(piece.size())});
    r0_zero[u] = (piece.array() == 0.0).all();
  }
  r0_valid = true;
  r0_time = time;
}

}  // namespace pc
