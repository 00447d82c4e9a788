#pragma once
// What the terms bound to one mesh share, computed once (a model's body terms -- elasticity, viscosity,
// inertia, piezoelectric coupling, permittivity -- all integrate over the body): the geometry of a region at
// a quadrature degree, and the pattern of a block between two spaces over it. Without it each term kept
// (and computed) its own copies, the largest part of a model's memory before its factorisation.
// Geometries and patterns live as long as a term holds them; spaces are told apart by identity.
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "assembly/block_pattern.hpp"
#include "assembly/mesh.hpp"
#include "assembly/region_geometry.hpp"

namespace pc {

class TermAssemblyCache {
 public:
  explicit TermAssemblyCache(const Mesh& mesh) : mesh_(mesh) {}
  TermAssemblyCache(const TermAssemblyCache&) = delete;
  TermAssemblyCache& operator=(const TermAssemblyCache&) = delete;

  const Mesh& mesh() const { return mesh_; }
  // From now on, geometries hold only the elements of the flagged cells (one flag per mesh cell; empty:
  // all). Before the first geometry: those made already would hold other elements.
  void set_owned_cells(std::vector<char> owned);
  std::shared_ptr<const RegionGeometry> geometry(const std::string& region, int degree);
  // The spaces must outlive the cache (a model's do: they are its fields').
  std::shared_ptr<const BlockPattern> pattern(const std::shared_ptr<const RegionGeometry>& geometry,
                                              const FESpace& test, const FESpace& trial);
  // The pattern depends on the region's elements and the spaces, not on the geometry's quadrature: terms
  // of other degrees over the region (inertia's and elasticity's) share it.

 private:
  const Mesh& mesh_;
  std::vector<char> owned_cells_;
  // Held by the terms, not here: a geometry no term holds any more (linear terms release theirs once
  // assembled, TermAssembly::release_geometry) is freed, and made again if asked for.
  std::map<std::pair<std::string, int>, std::weak_ptr<const RegionGeometry>> geometries_;
  std::map<std::tuple<std::string, const FESpace*, const FESpace*>, std::weak_ptr<const BlockPattern>> patterns_;
};

}  // namespace pc
