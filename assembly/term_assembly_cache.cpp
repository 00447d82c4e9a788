#include "assembly/term_assembly_cache.hpp"

#include "assembly/error.hpp"

namespace pc {

void TermAssemblyCache::set_owned_cells(std::vector<char> owned) {
  require(geometries_.empty(), "TermAssemblyCache: set_owned_cells() after a geometry was made");
  require(owned.empty() || int(owned.size()) == mesh_.num_cells(), "TermAssemblyCache: ", owned.size(),
          " ownership flags for a mesh of ", mesh_.num_cells(), " cells");
  owned_cells_ = std::move(owned);
}

std::shared_ptr<const RegionGeometry> TermAssemblyCache::geometry(const std::string& region, int degree) {
  std::weak_ptr<const RegionGeometry>& slot = geometries_[{region, degree}];
  std::shared_ptr<const RegionGeometry> held = slot.lock();
  if (!held) {
    held = std::make_shared<const RegionGeometry>(mesh_, region, degree, owned_cells_);
    slot = held;
  }
  return held;
}

std::shared_ptr<const BlockPattern> TermAssemblyCache::pattern(const std::shared_ptr<const RegionGeometry>& geometry,
                                                               const FESpace& test, const FESpace& trial) {
  require(geometry != nullptr && &geometry->mesh() == &mesh_ && &test.mesh() == &mesh_ && &trial.mesh() == &mesh_,
          "TermAssemblyCache: a pattern of another mesh");
  std::weak_ptr<const BlockPattern>& slot = patterns_[{geometry->region(), &test, &trial}];
  std::shared_ptr<const BlockPattern> held = slot.lock();
  if (!held) {
    held = std::make_shared<const BlockPattern>(make_block_pattern(*geometry, test, trial));
    slot = held;
  }
  return held;
}

void TermAssemblyCache::forget_patterns() { patterns_.clear(); }

}  // namespace pc
