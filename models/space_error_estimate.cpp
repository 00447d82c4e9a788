#include "models/space_error_estimate.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/QR>

#include "assembly/cell_geometry.hpp"
#include "assembly/error.hpp"
#include "assembly/quadrature.hpp"
#include "assembly/region_geometry.hpp"
#include "bricks/voigt.hpp"

namespace pc {
namespace {

// The centre of a reference cell: the mean of its vertices.
std::array<double, 3> reference_centre(Shape shape) {
  std::array<double, 3> centre{};
  for (int k = 0; k < num_vertices(shape); ++k)
    for (int d = 0; d < 3; ++d) centre[d] += reference_vertex(shape, k)[d] / num_vertices(shape);
  return centre;
}

// Nodal averaging: at each node, the cells' gradients there weighted by the cells' measures. Width =
// components * dim values per scalar dof.
std::vector<double> averaged_nodal_gradients(const FESpace& space, const Eigen::VectorXd& f) {
  const Mesh& mesh = space.mesh();
  const int width = space.num_components() * mesh.dim();
  const ReferenceElement& element = space.element();
  std::vector<double> sum(size_t(space.num_scalar_dofs()) * width, 0.0), weight(space.num_scalar_dofs(), 0.0);
  std::vector<double> grad(width);
  for (int cell = 0; cell < mesh.num_cells(); ++cell) {
    if (!space.has_cell(cell)) continue;
    const double measure = mesh.cell_measure(cell);
    const auto dofs = space.cell_scalar_dofs(cell);
    for (size_t i = 0; i < dofs.size(); ++i) {
      space.gradient_in_cell(f, cell, element.dof_point(int(i)).data(), grad.data());
      for (int a = 0; a < width; ++a) sum[size_t(dofs[i]) * width + a] += measure * grad[a];
      weight[dofs[i]] += measure;
    }
  }
  for (int i = 0; i < space.num_scalar_dofs(); ++i)
    if (weight[i] > 0)
      for (int a = 0; a < width; ++a) sum[size_t(i) * width + a] /= weight[i];
  return sum;
}

// q(G): the Voigt strain of a gradient, or the gradient itself.
void measured(GradientMeasure measure, int dim, int components, const double* grad, double* q) {
  if (measure == GradientMeasure::Strain)
    strain_from_gradient(dim, grad, q);
  else
    std::copy(grad, grad + components * dim, q);
}

// q^T W q, W applied to each component's block for a gradient.
double weighted_square(GradientMeasure measure, const Eigen::MatrixXd& W, int blocks, const double* q) {
  const Eigen::Index n = W.rows();
  double sum = 0;  // written out: W * x would allocate a temporary at every quadrature point
  for (int b = 0; b < (measure == GradientMeasure::Strain ? 1 : blocks); ++b) {
    const double* x = q + b * n;
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j) sum += x[i] * W(i, j) * x[j];
  }
  return sum;
}

// The checks both norms make; returns the width of q.
int check_measure(const std::string& what, const FESpace& space, const Eigen::VectorXd& coefficients,
                  GradientMeasure measure, const Eigen::MatrixXd& weight) {
  const int dim = space.mesh().dim(), components = space.num_components();
  require(coefficients.size() == space.num_dofs(), what, ": ", coefficients.size(), " coefficients, the space has ",
          space.num_dofs(), " dofs");
  require(measure == GradientMeasure::Gradient || components == dim, what, ": a strain needs ", dim,
          " components, the field has ", components);
  const int n = measure == GradientMeasure::Strain ? voigt_size(dim) : dim;
  require(weight.rows() == n && weight.cols() == n, what, ": the weight is ", weight.rows(), " x ", weight.cols(),
          ", the ", measure == GradientMeasure::Strain ? "strain" : "gradient", " needs ", n, " x ", n);
  return measure == GradientMeasure::Strain ? n : components * dim;
}

}  // namespace

// Superconvergent patch recovery of a first-order field (Zienkiewicz and Zhu, 1992). The gradient at a
// cell's centre is superconvergent; around each node not on the domain's boundary, a linear polynomial
// is fitted to the centre gradients of its cells by least squares, and its value at the node is the
// recovered one. A boundary node, whose patch is one-sided, takes the mean of the fits of the interior
// nodes it shares a cell with, evaluated at it (its own fit, or the nodal average, if it has none): the
// nodal average of a boundary node is only first order, and it is where contact and clamps put the error.
// The fit's coefficients are M G (M = P^+, G the patch's centre gradients), so a fit evaluated anywhere is
// a row of weights on the patch's cells, the same for every gradient component: those rows are kept.
SpaceErrorEstimator::SpaceErrorEstimator(const FESpace& space) : space_(space) {
  if (space.order() != 1) return;
  const Mesh& mesh = space.mesh();
  const int dim = mesh.dim(), n = space.num_scalar_dofs();
  const Shape shape = mesh.cell_shape();
  std::vector<std::vector<int>> patch(n);
  std::vector<std::array<double, 3>> centre_point(mesh.num_cells());
  // A face of the space's domain belongs to one of its cells: its dofs are the boundary's. Faces as sorted
  // vertex dofs (padded with -1), sorted, so that a face seen once is a run of one.
  std::vector<std::array<int, 4>> faces;
  for (int cell = 0; cell < mesh.num_cells(); ++cell) {
    if (!space.has_cell(cell)) continue;
    const auto dofs = space.cell_scalar_dofs(cell);
    for (int dof : dofs) patch[dof].push_back(cell);
    for (int k = 0; k < num_vertices(shape); ++k)
      for (int d = 0; d < dim; ++d) centre_point[cell][d] += mesh.node(mesh.cell(cell)[k])[d] / num_vertices(shape);
    for (int face = 0; face < num_faces(shape); ++face) {
      std::array<int, 4> key{-1, -1, -1, -1};
      const auto local = face_vertices(shape, face);
      for (size_t k = 0; k < local.size(); ++k) key[k] = dofs[local[k]];
      std::sort(key.begin(), key.begin() + local.size());
      faces.push_back(key);
    }
  }
  std::sort(faces.begin(), faces.end());
  std::vector<char> on_boundary(n, 0);
  for (size_t i = 0; i < faces.size();) {
    size_t j = i + 1;
    while (j < faces.size() && faces[j] == faces[i]) ++j;
    if (j == i + 1)
      for (int dof : faces[i])
        if (dof >= 0) on_boundary[dof] = 1;
    i = j;
  }

  // The fit around a node, as M ((dim + 1) x patch cells) for a + b . (x - x_node) / h, or none when its
  // patch has too few cells or they lie so that the fit is not unique.
  std::vector<Eigen::MatrixXd> fits(n);
  std::vector<double> patch_size(n, 0.0);
  const auto at = [&](int dof) { return space.scalar_dof_point(dof); };
  for (int node = 0; node < n; ++node) {
    const std::vector<int>& cells = patch[node];
    if (int(cells.size()) < dim + 1) continue;
    const auto x = at(node);
    double h = 0;
    for (int cell : cells)
      for (int d = 0; d < dim; ++d) h = std::max(h, std::abs(centre_point[cell][d] - x[d]));
    Eigen::MatrixXd P(cells.size(), dim + 1);
    for (size_t r = 0; r < cells.size(); ++r) {
      P(Eigen::Index(r), 0) = 1;
      for (int d = 0; d < dim; ++d) P(Eigen::Index(r), d + 1) = (centre_point[cells[r]][d] - x[d]) / h;
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(P);
    if (qr.rank() < dim + 1) continue;
    fits[node] = qr.solve(Eigen::MatrixXd::Identity(P.rows(), P.rows()));
    patch_size[node] = h;
  }

  const auto centre = reference_centre(shape);
  const int nloc = space.element().num_dofs();
  centre_shape_gradients_.assign(size_t(mesh.num_cells()) * nloc * dim, 0.0);
  for (int cell = 0; cell < mesh.num_cells(); ++cell)
    if (space.has_cell(cell))
      space.shape_gradients_in_cell(cell, centre.data(), centre_shape_gradients_.data() + size_t(cell) * nloc * dim);

  start_.assign(1, 0);
  std::vector<std::pair<int, double>> row;  // (cell, weight) of the node being recovered
  const auto add_fit_at = [&](int fitted, const std::array<double, 3>& x, double share) {
    for (Eigen::Index r = 0; r < fits[fitted].cols(); ++r) {
      double w = fits[fitted](0, r);
      for (int d = 0; d < dim; ++d) w += fits[fitted](d + 1, r) * (x[d] - at(fitted)[d]) / patch_size[fitted];
      row.emplace_back(patch[fitted][size_t(r)], share * w);
    }
  };
  for (int node = 0; node < n; ++node) {
    row.clear();
    if (!on_boundary[node] && fits[node].size() > 0) {
      add_fit_at(node, at(node), 1.0);
    } else {
      std::vector<int> neighbours;
      for (int cell : patch[node])
        for (int other : space.cell_scalar_dofs(cell))
          if (!on_boundary[other] && fits[other].size() > 0) neighbours.push_back(other);
      std::sort(neighbours.begin(), neighbours.end());
      neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
      if (neighbours.empty() && fits[node].size() > 0) neighbours.push_back(node);
      if (neighbours.empty()) {
        averaged_.push_back(node);
        averaged_cells_.push_back(patch[node]);
      }
      for (int other : neighbours) add_fit_at(other, at(node), 1.0 / double(neighbours.size()));
    }
    // One weight per cell: the neighbours' patches overlap.
    std::sort(row.begin(), row.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (size_t k = 0; k < row.size(); ++k) {
      if (k > 0 && row[k].first == cell_.back() && int(cell_.size()) > start_.back()) {
        weight_.back() += row[k].second;
        continue;
      }
      cell_.push_back(row[k].first);
      weight_.push_back(row[k].second);
    }
    start_.push_back(int(cell_.size()));
  }
}

bool SpaceErrorEstimator::serves(const FESpace& other) const {
  if (&other == &space_) return true;
  if (&other.mesh() != &space_.mesh() || &other.element() != &space_.element() ||
      other.num_scalar_dofs() != space_.num_scalar_dofs())
    return false;
  for (int cell = 0; cell < space_.mesh().num_cells(); ++cell) {
    if (other.has_cell(cell) != space_.has_cell(cell)) return false;
    if (!space_.has_cell(cell)) continue;
    const auto mine = space_.cell_scalar_dofs(cell), theirs = other.cell_scalar_dofs(cell);
    if (!std::equal(mine.begin(), mine.end(), theirs.begin(), theirs.end())) return false;
  }
  return true;
}

std::vector<double> SpaceErrorEstimator::recovered_nodal_gradients(const FESpace& space,
                                                                   const Eigen::VectorXd& f) const {
  if (space.order() != 1) return averaged_nodal_gradients(space, f);
  const Mesh& mesh = space.mesh();
  const int dim = mesh.dim(), components = space.num_components(), width = components * dim;
  const int n = space.num_scalar_dofs(), nloc = space.element().num_dofs();
  // The gradient of f in a cell at a point whose shape gradients are dN (nloc x dim).
  const auto cell_gradient = [&](int cell, const double* dN, double* out) {
    const auto dofs = space.cell_scalar_dofs(cell);
    std::fill(out, out + width, 0.0);
    for (int i = 0; i < nloc; ++i)
      for (int c = 0; c < components; ++c) {
        const double value = f[space.dof(dofs[i], c)];
        for (int d = 0; d < dim; ++d) out[c * dim + d] += value * dN[i * dim + d];
      }
  };
  std::vector<double> centre_gradient(size_t(mesh.num_cells()) * width, 0.0);
  for (int cell = 0; cell < mesh.num_cells(); ++cell)
    if (space.has_cell(cell))
      cell_gradient(cell, centre_shape_gradients_.data() + size_t(cell) * nloc * dim,
                    centre_gradient.data() + size_t(cell) * width);
  std::vector<double> recovered(size_t(n) * width, 0.0);
  for (int node = 0; node < n; ++node) {
    double* out = recovered.data() + size_t(node) * width;
    for (int k = start_[node]; k < start_[node + 1]; ++k) {
      const double* g = centre_gradient.data() + size_t(cell_[k]) * width;
      for (int a = 0; a < width; ++a) out[a] += weight_[k] * g[a];
    }
  }
  // A node with no fit near it: the average of its cells' gradients there, weighted by their measures.
  std::vector<double> dN(size_t(nloc) * dim), gradient(width);
  for (size_t k = 0; k < averaged_.size(); ++k) {
    const int node = averaged_[k];
    double* out = recovered.data() + size_t(node) * width;
    double total = 0;
    for (int cell : averaged_cells_[k]) {
      const auto dofs = space.cell_scalar_dofs(cell);
      const int local = int(std::find(dofs.begin(), dofs.end(), node) - dofs.begin());
      space.shape_gradients_in_cell(cell, space.element().dof_point(local).data(), dN.data());
      cell_gradient(cell, dN.data(), gradient.data());
      const double measure = mesh.cell_measure(cell);
      for (int a = 0; a < width; ++a) out[a] += measure * gradient[a];
      total += measure;
    }
    if (total > 0)
      for (int a = 0; a < width; ++a) out[a] /= total;
  }
  return recovered;
}

SpaceErrorField SpaceErrorEstimator::estimate(const std::string& field, const Eigen::VectorXd& coefficients,
                                              GradientMeasure measure, const Eigen::MatrixXd& weight) const {
  return estimate(field, space_, coefficients, measure, weight);
}

SpaceErrorField SpaceErrorEstimator::estimate(const std::string& field, const FESpace& space,
                                              const Eigen::VectorXd& coefficients, GradientMeasure measure,
                                              const Eigen::MatrixXd& weight) const {
  require(serves(space), "space error estimate of '", field,
          "': the field's space has other cells or scalar dofs than the estimator's");
  const Mesh& mesh = space.mesh();
  const int dim = mesh.dim(), components = space.num_components();
  const int measured_width =
      check_measure("space error estimate of '" + field + "'", space, coefficients, measure, weight);
  const int width = components * dim;
  const std::vector<double> nodal = recovered_nodal_gradients(space, coefficients);
  const ReferenceElement& element = space.element();
  // Degree 2p: the squared difference of two gradients of the space's degree p - 1 (p on a Q cell's
  // coordinates) is integrated exactly on simplices, well enough elsewhere.
  const QuadratureRule& rule = quadrature(mesh.cell_shape(), 2 * space.order());
  const int nq = rule.size(), nloc = element.num_dofs();
  std::vector<double> N(size_t(nq) * nloc), dN(size_t(nq) * nloc * dim);
  for (int q = 0; q < nq; ++q) {
    element.values(rule.points[q].data(), N.data() + size_t(q) * nloc);
    element.gradients(rule.points[q].data(), dN.data() + size_t(q) * nloc * dim);
  }
  std::vector<double> discrete(width), recovered(width), q_discrete(measured_width), q_recovered(measured_width);
  std::vector<double> values(size_t(nloc) * components);

  SpaceErrorField result;
  result.field = field;
  result.cells.assign(mesh.num_cells(), 0.0);
  double estimate_squared = 0, norm_squared = 0;
  double J[9], G[9];
  const bool affine = is_simplex(mesh.cell_shape());
  // P1 on a simplex: the discrete gradient is the same at every point of the cell (the same operations on
  // the same numbers), so it, its measure and its weighted square are found once per cell, to the bit what
  // each point found: the estimates at a 3D run's output steps were a tenth of its work.
  const bool constant_gradient = affine && space.order() == 1;
  std::vector<double> cell_nodal(size_t(nloc) * width);  // the recovered nodal gradients of the cell's dofs
  for (int cell = 0; cell < mesh.num_cells(); ++cell) {
    if (!space.has_cell(cell)) continue;
    const auto dofs = space.cell_scalar_dofs(cell);
    for (size_t i = 0; i < dofs.size(); ++i) {
      for (int c = 0; c < components; ++c) values[i * components + c] = coefficients[space.dof(dofs[i], c)];
      std::copy_n(nodal.begin() + std::ptrdiff_t(size_t(dofs[i]) * width), width,
                  cell_nodal.begin() + std::ptrdiff_t(i * width));
    }
    double cell_squared = 0, det = 0, discrete_square = 0;
    for (int q = 0; q < nq; ++q) {
      if (q == 0 || !affine) {  // a simplex's map is affine: one Jacobian for all its points
        det = cell_jacobian(mesh, cell, rule.points[q].data(), J);
        require(det > 0, "space error estimate of '", field, "': cell ", cell, " has det J = ", det,
                " (inverted cell)");
        inverse_transpose_jacobian(dim, J, det, G);
      }
      if (q == 0 || !constant_gradient) {
        const double* dNq = dN.data() + size_t(q) * nloc * dim;
        std::fill(discrete.begin(), discrete.end(), 0.0);
        for (size_t i = 0; i < dofs.size(); ++i)
          for (int d = 0; d < dim; ++d) {
            double g = 0;  // d N_i / d x_d = sum_k d N_i / d xi_k * d xi_k / d x_d
            for (int k = 0; k < dim; ++k) g += dNq[i * dim + k] * G[d * dim + k];
            for (int c = 0; c < components; ++c) discrete[c * dim + d] += g * values[i * components + c];
          }
        measured(measure, dim, components, discrete.data(), q_discrete.data());
        discrete_square = weighted_square(measure, weight, components, q_discrete.data());
      }
      const double* Nq = N.data() + size_t(q) * nloc;
      std::fill(recovered.begin(), recovered.end(), 0.0);
      for (size_t i = 0; i < dofs.size(); ++i)
        for (int a = 0; a < width; ++a) recovered[a] += Nq[i] * cell_nodal[i * width + a];
      const double w = rule.weights[q] * det;
      measured(measure, dim, components, recovered.data(), q_recovered.data());
      norm_squared += w * discrete_square;
      for (int a = 0; a < measured_width; ++a) q_recovered[a] -= q_discrete[a];
      cell_squared += w * weighted_square(measure, weight, components, q_recovered.data());
    }
    result.cells[cell] = std::sqrt(std::max(cell_squared, 0.0));
    estimate_squared += cell_squared;
  }
  result.estimate = std::sqrt(std::max(estimate_squared, 0.0));
  result.norm = std::sqrt(std::max(norm_squared, 0.0));
  return result;
}

SpaceErrorField recovery_error_estimate(const std::string& field, const FESpace& space,
                                        const Eigen::VectorXd& coefficients, GradientMeasure measure,
                                        const Eigen::MatrixXd& weight) {
  return SpaceErrorEstimator(space).estimate(field, coefficients, measure, weight);
}

double energy_norm_difference(const FESpace& space, const Eigen::VectorXd& f, const PointGradient& g,
                              GradientMeasure measure, const Eigen::MatrixXd& weight) {
  const int measured_width = check_measure("energy norm difference", space, f, measure, weight);
  const int dim = space.mesh().dim(), components = space.num_components(), width = components * dim;
  const RegionGeometry geometry(space.mesh(), "all", 2 * space.order() + 2);
  std::vector<double> gf(width), gg(width), qf(measured_width), qg(measured_width);
  double sum = 0;
  for (int e = 0; e < geometry.num_elements(); ++e) {
    if (!space.has_cell(geometry.cell(e))) continue;
    for (int q = 0; q < geometry.num_points(); ++q) {
      space.gradient_in_cell(f, geometry.cell(e), geometry.reference_points(-1)[q].data(), gf.data());
      g(geometry.point(e, q).data(), gg.data());
      measured(measure, dim, components, gf.data(), qf.data());
      measured(measure, dim, components, gg.data(), qg.data());
      for (int a = 0; a < measured_width; ++a) qf[a] -= qg[a];
      sum += geometry.weight(e, q) * weighted_square(measure, weight, components, qf.data());
    }
  }
  return std::sqrt(std::max(sum, 0.0));
}

const SpaceErrorField* SpaceErrorEstimate::field(const std::string& name) const {
  for (const SpaceErrorField& f : fields)
    if (f.field == name) return &f;
  return nullptr;
}

double SpaceErrorEstimate::max_relative() const {
  double largest = 0;
  for (const SpaceErrorField& f : fields) largest = std::max(largest, f.relative());
  return largest;
}

std::vector<double> SpaceErrorEstimate::relative_cell_indicators() const {
  std::vector<double> combined(fields.empty() ? 0 : fields.front().cells.size(), 0.0);
  for (const SpaceErrorField& f : fields)
    if (f.norm > 0)
      for (size_t c = 0; c < combined.size(); ++c) combined[c] += (f.cells[c] / f.norm) * (f.cells[c] / f.norm);
  for (double& c : combined) c = std::sqrt(c);
  return combined;
}

}  // namespace pc
