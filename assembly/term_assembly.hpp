#pragma once
// A term bound to a region and to the FE spaces of its fields: the engine's element loop. Built once, it
// holds the shape-function tables at the region's quadrature points, the sparsity pattern of each tangent
// block (rows: dofs of the test field's space, columns: dofs of the trial field's space), into which each
// element's local entries are added where a search of their row finds them (a table of those slots, an
// int per element entry, was the largest part of a model's memory, for work done once per change of a
// linear brick's data). The geometry and the patterns can come from a TermAssemblyCache, shared with the
// other terms over the same region and spaces; the tangent blocks' values are the term's own.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "assembly/block_pattern.hpp"
#include "assembly/fe_space.hpp"
#include "assembly/region_geometry.hpp"
#include "assembly/sparse.hpp"
#include "assembly/term.hpp"
#include "assembly/term_assembly_cache.hpp"

namespace pc {

class TermAssembly {
 public:
  // spaces[f] is the space of the term's field f. The geometry's region kind must match the term's
  // integration, and every element of the region must lie in every space.
  TermAssembly(std::shared_ptr<const Term> term, std::shared_ptr<const RegionGeometry> geometry,
               std::vector<const FESpace*> spaces);
  // The same, with a geometry of its own at the degree the term asks for its highest field order.
  TermAssembly(std::shared_ptr<const Term> term, const std::string& region, std::vector<const FESpace*> spaces);
  // The same, with the geometry and the block patterns the cache holds (made there if new), shared with the
  // cache's other terms. The cache must outlive the assembly.
  TermAssembly(std::shared_ptr<const Term> term, const std::string& region, std::vector<const FESpace*> spaces,
               TermAssemblyCache& cache);

  const Term& term() const { return *term_; }
  // The geometry, made again from the cache if release_geometry() let it go.
  const RegionGeometry& geometry() const;
  // Lets go of the geometry, for a term whose blocks stay as assembled (a linear term's): the body's
  // geometries were 7.6 MB at the paper's 240 x 80, kept for the whole run to serve one assembly. If the
  // term is assembled again (its data changed), its geometry is made again from the cache, the same bits,
  // and kept from then on. Nothing happens to a term built without a cache, or that released it before.
  void release_geometry();
  const FESpace& space(int field) const { return *spaces_[field]; }
  // Tangent block of coupling k, with the values of the last assembly that asked for tangents: the term's
  // own values over a pattern it may share (a view, valid while the assembly lives).
  CsrView block(int k) const;

  // values[f]: coefficients of field f. Residual blocks are added to residuals[t] (one per test field,
  // null to skip); tangent blocks are overwritten when tangent is true.
  void assemble(std::span<const Eigen::VectorXd* const> values, double time,
                std::span<Eigen::VectorXd* const> residuals, bool tangent);

  // Number of elements assembled so far (lets callers check that a cache avoided an element loop).
  std::int64_t elements_assembled() const { return elements_assembled_; }

 private:
  struct ShapeTable {
    std::vector<int> local_dofs;  // the element's local dofs used (all, or those on the face)
    std::vector<double> N;        // [q * n + i]
    std::vector<double> dN;       // reference gradients [(q * n + i) * dim + d]; cells only
  };
  struct Workspace;
  TermAssembly(std::shared_ptr<const Term> term, std::shared_ptr<const RegionGeometry> geometry,
               std::vector<const FESpace*> spaces, TermAssemblyCache* cache);
  const ShapeTable& table(int field, int local_face) const;
  void element_dofs(int field, int element, std::vector<int>& dofs) const;
  void build_blocks(TermAssemblyCache* cache);
  // The phases of assemble().
  void check_arguments(std::span<const Eigen::VectorXd* const> values,
                       std::span<Eigen::VectorXd* const> residuals) const;
  void prepare(Workspace& w, const RegionGeometry& geo, double time) const;
  void interpolate(int e, const RegionGeometry& geo, std::span<const Eigen::VectorXd* const> values,
                   Workspace& w) const;
  void compute(int e, const RegionGeometry& geo, std::span<const Eigen::VectorXd* const> values, bool want_residual,
               bool tangent, Workspace& w) const;
  void scatter(const Workspace& w, std::span<Eigen::VectorXd* const> residuals, bool tangent);
  void run_element_loop(const RegionGeometry& geo, std::span<const Eigen::VectorXd* const> values, double time,
                        std::span<Eigen::VectorXd* const> residuals, bool want_residual, bool tangent);

  std::shared_ptr<const Term> term_;
  mutable std::shared_ptr<const RegionGeometry> geometry_;  // null after release_geometry()
  TermAssemblyCache* cache_ = nullptr;                      // where a released geometry is made again
  std::string region_;
  int degree_ = 0;
  bool released_ = false;
  std::vector<const FESpace*> spaces_;
  std::vector<std::vector<ShapeTable>> tables_;  // [field][local_face + 1]
  // Coupling k's block: the pattern (shared through the cache with the other terms over the region and
  // spaces: inertia, viscosity and elasticity on the body's velocity keep one) and the term's own values.
  std::vector<std::shared_ptr<const BlockPattern>> patterns_;
  std::vector<std::vector<double>> block_values_;
  std::int64_t elements_assembled_ = 0;

  // What one element needs while it is computed: a thread has one at a time, a loop on several threads
  // one per element of a chunk.
  struct Workspace {
    ElementData data;
    LocalSystem local;
    std::vector<std::vector<int>> dofs;
  };
  // A term whose tangent is assembled again and again (a contact law's, at every Newton iteration) keeps
  // its workspaces from its second tangent assembly on: made afresh at each call, a chunk's workspaces and
  // their vectors were tens of thousands of allocations per assembly of a 3D contact face. A linear term,
  // assembled once, keeps none (a chunk of them would outweigh its block).
  std::vector<Workspace> kept_workspaces_;
  int tangent_assemblies_ = 0;
};

}  // namespace pc
