#include "assembly/term_assembly_cache.hpp"

#include "assembly/error.hpp"

namespace pc {
namespace {

// The entry the cache holds weakly under `key`, or a new one from make() if none is alive.
template <class Map, class Key, class Make> auto held_or_made(Map& map, const Key& key, Make&& make) {
  auto held = map[key].lock();
  if (!held) {
    held = make();
    map[key] = held;
  }
  return held;
}

}  // namespace

void TermAssemblyCache::set_owned_cells(std::vector<char> owned) {
  require(geometries_.empty(), "TermAssemblyCache: set_owned_cells() after a geometry was made");
  require(owned.empty() || int(owned.size()) == mesh_.num_cells(), "TermAssemblyCache: ", owned.size(),
          " ownership flags for a mesh of ", mesh_.num_cells(), " cells");
  owned_cells_ = std::move(owned);
}

std::shared_ptr<const RegionGeometry> TermAssemblyCache::geometry(const std::string& region, int degree) {
  return held_or_made(geometries_, std::pair{region, degree},
                      [&] { return std::make_shared<const RegionGeometry>(mesh_, region, degree, owned_cells_); });
}

std::shared_ptr<const BlockPattern> TermAssemblyCache::pattern(const std::shared_ptr<const RegionGeometry>& geometry,
                                                               const FESpace& test, const FESpace& trial) {
  require(geometry != nullptr && &geometry->mesh() == &mesh_ && &test.mesh() == &mesh_ && &trial.mesh() == &mesh_,
          "TermAssemblyCache: a pattern of another mesh");
  return held_or_made(patterns_, std::tuple{geometry->region(), &test, &trial},
                      [&] { return std::make_shared<const BlockPattern>(make_block_pattern(*geometry, test, trial)); });
}

}  // namespace pc
