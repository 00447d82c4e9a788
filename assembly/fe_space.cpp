#include "assembly/fe_space.hpp"

#include <algorithm>
#include <map>

#include "assembly/cell_geometry.hpp"
#include "assembly/error.hpp"

namespace pc {
namespace {

// Global key of the mesh entity a local dof sits on: its dimension and its sorted vertex nodes (a cell
// interior is keyed by the cell itself so that it is never shared).
using EntityKey = std::pair<int, std::vector<int>>;

EntityKey entity_key(const Mesh& mesh, int cell, DofEntity entity) {
  const Shape shape = mesh.cell_shape();
  const auto nodes = mesh.cell(cell);
  std::vector<int> key;
  if (entity.dim == 0) {
    key = {nodes[entity.index]};
  } else if (entity.dim == 1) {
    for (int v : edge_vertices(shape, entity.index)) key.push_back(nodes[v]);
  } else if (entity.dim < dimension(shape)) {
    for (int v : face_vertices(shape, entity.index)) key.push_back(nodes[v]);
  } else {
    return {entity.dim, {-1 - cell}};
  }
  std::sort(key.begin(), key.end());
  return {entity.dim, key};
}

}  // namespace

FESpace::FESpace(std::shared_ptr<const Mesh> mesh, int order, int num_components, const std::string& cell_region)
    : mesh_(std::move(mesh)),
      element_(&ReferenceElement::get(mesh_->cell_shape(), order)),
      num_components_(num_components) {
  require(num_components >= 1 && num_components <= 3, "FESpace: num_components must be 1, 2 or 3, got ",
          num_components);
  const Mesh& m = *mesh_;
  std::vector<int> cells;
  if (cell_region.empty()) {
    cells.resize(m.num_cells());
    for (int c = 0; c < m.num_cells(); ++c) cells[c] = c;
  } else {
    cells = m.cell_region(cell_region);
  }

  // Vertex dofs are numbered in node order so that P1/Q1 dofs follow the mesh numbering (good locality
  // for structured and gmsh meshes alike); higher entities follow in the order cells meet them.
  const int n_local = element_->num_dofs();
  std::map<EntityKey, int> numbering;
  std::vector<int> vertex_dof(m.num_nodes(), -1);
  for (int c : cells)
    for (int v : m.cell(c)) vertex_dof[v] = 0;
  for (int& d : vertex_dof)
    if (d == 0) d = num_scalar_dofs_++;

  cell_offset_.assign(m.num_cells(), -1);
  cell_dofs_.reserve(cells.size() * n_local);
  for (int c : cells) {
    cell_offset_[c] = static_cast<int>(cell_dofs_.size());
    for (int i = 0; i < n_local; ++i) {
      const DofEntity entity = element_->dof_entity(i);
      if (entity.dim == 0) {
        cell_dofs_.push_back(vertex_dof[m.cell(c)[entity.index]]);
        continue;
      }
      auto [it, inserted] = numbering.try_emplace(entity_key(m, c, entity), num_scalar_dofs_);
      if (inserted) ++num_scalar_dofs_;
      cell_dofs_.push_back(it->second);
    }
  }

  dof_points_.assign(num_scalar_dofs_, {0, 0, 0});
  for (int c : cells)
    for (int i = 0; i < n_local; ++i)
      dof_points_[cell_dofs_[cell_offset_[c] + i]] = map_to_physical(m, c, element_->dof_point(i).data());
}

std::span<const int> FESpace::cell_scalar_dofs(int cell) const {
  require(cell >= 0 && cell < mesh_->num_cells() && cell_offset_[cell] >= 0, "FESpace: cell ", cell,
          " is not in the space's region");
  return {cell_dofs_.data() + cell_offset_[cell], size_t(element_->num_dofs())};
}

std::vector<int> FESpace::scalar_dofs_on(const std::string& region) const {
  std::vector<int> dofs;
  if (mesh_->region_kind(region) == RegionKind::Cells) {
    for (int c : mesh_->cell_region(region))
      if (has_cell(c))
        for (int d : cell_scalar_dofs(c)) dofs.push_back(d);
  } else {
    for (const FaceRef& f : mesh_->face_region(region)) {
      if (!has_cell(f.cell)) continue;
      const auto cell_dofs = cell_scalar_dofs(f.cell);
      for (int i : element_->face_dofs(f.local_face)) dofs.push_back(cell_dofs[i]);
    }
  }
  std::sort(dofs.begin(), dofs.end());
  dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
  return dofs;
}

std::vector<int> FESpace::dofs_on(const std::string& region, int component) const {
  require(component >= -1 && component < num_components_, "FESpace: component ", component,
          " out of range for a field with ", num_components_, " components");
  std::vector<int> dofs;
  for (int s : scalar_dofs_on(region))
    for (int c = 0; c < num_components_; ++c)
      if (component < 0 || c == component) dofs.push_back(dof(s, c));
  return dofs;
}

Eigen::VectorXd FESpace::interpolate(const std::function<void(const double* x, double* out)>& f) const {
  Eigen::VectorXd coefficients(num_dofs());
  for (int s = 0; s < num_scalar_dofs_; ++s) f(dof_points_[s].data(), coefficients.data() + dof(s, 0));
  return coefficients;
}

void FESpace::evaluate_in_cell(const Eigen::VectorXd& coefficients, int cell, const double* xi, double* out) const {
  require(coefficients.size() == num_dofs(), "FESpace: coefficient vector has ", coefficients.size(),
          " entries, the space has ", num_dofs(), " dofs");
  double N[27];
  element_->values(xi, N);
  const auto dofs = cell_scalar_dofs(cell);
  for (int c = 0; c < num_components_; ++c) {
    out[c] = 0;
    for (int i = 0; i < int(dofs.size()); ++i) out[c] += N[i] * coefficients[dof(dofs[i], c)];
  }
}

void FESpace::gradient_in_cell(const Eigen::VectorXd& coefficients, int cell, const double* xi, double* out) const {
  require(coefficients.size() == num_dofs(), "FESpace: coefficient vector has ", coefficients.size(),
          " entries, the space has ", num_dofs(), " dofs");
  const int dim = mesh_->dim();
  double dN[27 * 3];
  shape_gradients_in_cell(cell, xi, dN);
  const auto dofs = cell_scalar_dofs(cell);
  for (int c = 0; c < num_components_; ++c)
    for (int d = 0; d < dim; ++d) {
      double g = 0;
      for (int i = 0; i < int(dofs.size()); ++i) g += coefficients[dof(dofs[i], c)] * dN[i * dim + d];
      out[c * dim + d] = g;
    }
}

void FESpace::shape_gradients_in_cell(int cell, const double* xi, double* out) const {
  const int dim = mesh_->dim(), nloc = element_->num_dofs();
  double J[9], G[9], dN[27 * 3];
  const double det = cell_jacobian(*mesh_, cell, xi, J);
  inverse_transpose_jacobian(dim, J, det, G);
  element_->gradients(xi, dN);
  for (int i = 0; i < nloc; ++i)
    for (int d = 0; d < dim; ++d) {
      double g = 0;  // d N_i / d x_d = sum_k d N_i / d xi_k * d xi_k / d x_d
      for (int k = 0; k < dim; ++k) g += dN[i * dim + k] * G[d * dim + k];
      out[i * dim + d] = g;
    }
}

}  // namespace pc
