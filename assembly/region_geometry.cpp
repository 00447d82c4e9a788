#include "assembly/region_geometry.hpp"

#include <cmath>

#include <Eigen/Dense>

#include "assembly/cell_geometry.hpp"
#include "assembly/error.hpp"

namespace pc {
namespace {

std::array<double, 3> centroid(const Mesh& mesh, int cell) {
  std::array<double, 3> x{0, 0, 0};
  const auto nodes = mesh.cell(cell);
  for (int n : nodes)
    for (int d = 0; d < mesh.dim(); ++d) x[d] += mesh.node(n)[d] / double(nodes.size());
  return x;
}

// d xi / d s of the map from the face's reference shape into the cell (columns: face directions).
Eigen::Matrix<double, 3, 2> face_map_derivative(Shape cell, int face, const double* s) {
  Eigen::Matrix<double, 3, 2> T = Eigen::Matrix<double, 3, 2>::Zero();
  const int face_dim = dimension(cell) - 1;
  const double h = 0.5;  // the face maps are affine or bilinear: a central difference is exact
  for (int k = 0; k < face_dim; ++k) {
    double sp[2] = {s[0], face_dim > 1 ? s[1] : 0.0};
    double sm[2] = {sp[0], sp[1]};
    sp[k] += h;
    sm[k] -= h;
    const auto xp = face_to_cell(cell, face, sp);
    const auto xm = face_to_cell(cell, face, sm);
    for (int d = 0; d < 3; ++d) T(d, k) = (xp[d] - xm[d]) / (2 * h);
  }
  return T;
}

}  // namespace

RegionGeometry::RegionGeometry(const Mesh& mesh, const std::string& region, int degree,
                               std::span<const char> owned_cells)
    : mesh_(mesh),
      region_(region),
      integration_(mesh.region_kind(region) == RegionKind::Cells ? Integration::Cells : Integration::Faces) {
  const Shape shape = mesh.cell_shape();
  reference_points_.resize(num_faces(shape) + 1);
  if (integration_ == Integration::Cells) {
    rule_ = &quadrature(shape, degree);
    reference_points_[0] = rule_->points;
    compute_cells(owned_cells);
  } else {
    rule_ = &quadrature(face_shape(shape, 0), degree);
    for (int f = 0; f < num_faces(shape); ++f)
      for (const auto& s : rule_->points) reference_points_[f + 1].push_back(face_to_cell(shape, f, s.data()));
    compute_faces(owned_cells);
  }
}

void RegionGeometry::compute_cells(std::span<const char> owned_cells) {
  const int dim = mesh_.dim();
  const int nq = num_points();
  require(owned_cells.empty() || int(owned_cells.size()) == mesh_.num_cells(), "RegionGeometry: ", owned_cells.size(),
          " ownership flags for a mesh of ", mesh_.num_cells(), " cells");
  for (int c : mesh_.cell_region(region_))
    if (owned_cells.empty() || owned_cells[size_t(c)]) cells_.push_back(c);
  const size_t n = cells_.size() * nq;
  weights_.resize(n);
  points_.resize(n);
  inverse_jacobians_.resize(n * dim * dim);
  double J[9];
  for (int e = 0; e < num_elements(); ++e) {
    for (int q = 0; q < nq; ++q) {
      const double* xi = rule_->points[q].data();
      const double det = cell_jacobian(mesh_, cells_[e], xi, J);
      require(det > 0, "cell ", cells_[e], " has det J = ", det, " at a quadrature point (inverted cell)");
      const size_t at = e * nq + q;
      weights_[at] = rule_->weights[q] * det;
      points_[at] = map_to_physical(mesh_, cells_[e], xi);
      inverse_transpose_jacobian(dim, J, det, &inverse_jacobians_[at * dim * dim]);
    }
  }
}

void RegionGeometry::compute_faces(std::span<const char> owned_cells) {
  const int dim = mesh_.dim();
  const int nq = num_points();
  const Shape shape = mesh_.cell_shape();
  require(owned_cells.empty() || int(owned_cells.size()) == mesh_.num_cells(), "RegionGeometry: ", owned_cells.size(),
          " ownership flags for a mesh of ", mesh_.num_cells(), " cells");
  for (const FaceRef& f : mesh_.face_region(region_)) {
    if (!owned_cells.empty() && !owned_cells[size_t(f.cell)]) continue;
    cells_.push_back(f.cell);
    local_faces_.push_back(f.local_face);
  }
  const size_t n = cells_.size() * nq;
  weights_.resize(n);
  points_.resize(n);
  normals_.resize(n);
  double J[9];
  for (int e = 0; e < num_elements(); ++e) {
    const int cell = cells_[e];
    const int face = local_faces_[e];
    const auto center = centroid(mesh_, cell);
    for (int q = 0; q < nq; ++q) {
      const double* xi = reference_points_[face + 1][q].data();
      cell_jacobian(mesh_, cell, xi, J);
      const Eigen::Matrix<double, 3, 2> dxi_ds = face_map_derivative(shape, face, rule_->points[q].data());
      // Physical tangents t_k = J dxi/ds_k; measure factor and normal from them.
      Eigen::Vector3d t[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
      for (int k = 0; k < dim - 1; ++k)
        for (int a = 0; a < dim; ++a)
          for (int b = 0; b < dim; ++b) t[k][a] += J[a * dim + b] * dxi_ds(b, k);
      Eigen::Vector3d normal = dim == 2 ? Eigen::Vector3d(t[0][1], -t[0][0], 0) : Eigen::Vector3d(t[0].cross(t[1]));
      const double factor = normal.norm();
      require(factor > 0, "face ", face, " of cell ", cell, " is degenerate");
      normal /= factor;
      const size_t at = e * nq + q;
      points_[at] = map_to_physical(mesh_, cell, xi);
      Eigen::Vector3d outward(points_[at][0] - center[0], points_[at][1] - center[1], points_[at][2] - center[2]);
      if (normal.dot(outward) < 0) normal = -normal;
      weights_[at] = rule_->weights[q] * factor;
      normals_[at] = {normal[0], normal[1], normal[2]};
    }
  }
}

}  // namespace pc
