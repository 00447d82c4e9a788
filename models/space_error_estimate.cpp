#include "models/space_error_estimate.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/QR>

#include "assembly/error.hpp"
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

// Superconvergent patch recovery of a first-order field (Zienkiewicz and Zhu, 1992). The gradient at a
// cell's centre is superconvergent; around each node not on the domain's boundary, a linear polynomial
// is fitted to the centre gradients of its cells by least squares, and its value at the node is the
// recovered one. A boundary node, whose patch is one-sided, takes the mean of the fits of the interior
// nodes it shares a cell with, evaluated at it (its own fit, or the nodal average, if it has none): the
// nodal average of a boundary node is only first order, and it is where contact and clamps put the error.
std::vector<double> patch_recovered_nodal_gradients(const FESpace& space, const Eigen::VectorXd& f) {
  const Mesh& mesh = space.mesh();
  const int dim = mesh.dim(), width = space.num_components() * dim, n = space.num_scalar_dofs();
  const Shape shape = mesh.cell_shape();
  const auto centre = reference_centre(shape);
  std::vector<std::vector<int>> patch(n);
  std::vector<double> centre_gradient(size_t(mesh.num_cells()) * width);
  std::vector<std::array<double, 3>> centre_point(mesh.num_cells());
  // A face of the space's domain belongs to one of its cells: its dofs are the boundary's. Faces as sorted
  // vertex dofs (padded with -1), sorted, so that a face seen once is a run of one.
  std::vector<std::array<int, 4>> faces;
  for (int cell = 0; cell < mesh.num_cells(); ++cell) {
    if (!space.has_cell(cell)) continue;
    const auto dofs = space.cell_scalar_dofs(cell);
    for (int dof : dofs) patch[dof].push_back(cell);
    space.gradient_in_cell(f, cell, centre.data(), centre_gradient.data() + size_t(cell) * width);
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

  // The fit around a node: coefficients ((dim + 1) x width) of a + b . (x - x_node) / h, or none when
  // its patch has too few cells or they lie so that the fit is not unique.
  using Fit = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic>;
  std::vector<Fit> fits(n);
  std::vector<double> patch_size(n, 0.0);
  const auto at = [&](int dof) { return space.scalar_dof_point(dof); };
  for (int node = 0; node < n; ++node) {
    const std::vector<int>& cells = patch[node];
    if (int(cells.size()) < dim + 1) continue;
    const auto x = at(node);
    double h = 0;
    for (int cell : cells)
      for (int d = 0; d < dim; ++d) h = std::max(h, std::abs(centre_point[cell][d] - x[d]));
    Eigen::MatrixXd P(cells.size(), dim + 1), G(cells.size(), width);
    for (size_t r = 0; r < cells.size(); ++r) {
      P(Eigen::Index(r), 0) = 1;
      for (int d = 0; d < dim; ++d) P(Eigen::Index(r), d + 1) = (centre_point[cells[r]][d] - x[d]) / h;
      for (int a = 0; a < width; ++a) G(Eigen::Index(r), a) = centre_gradient[size_t(cells[r]) * width + a];
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(P);
    if (qr.rank() < dim + 1) continue;
    fits[node] = qr.solve(G);
    patch_size[node] = h;
  }
  const auto evaluate = [&](int node, const std::array<double, 3>& x, double* out) {
    for (int a = 0; a < width; ++a) {
      double value = fits[node](0, a);
      for (int d = 0; d < dim; ++d) value += fits[node](d + 1, a) * (x[d] - at(node)[d]) / patch_size[node];
      out[a] = value;
    }
  };

  std::vector<double> recovered(size_t(n) * width, 0.0);
  const std::vector<double> averaged = averaged_nodal_gradients(space, f);
  std::vector<double> value(width);
  for (int node = 0; node < n; ++node) {
    double* out = recovered.data() + size_t(node) * width;
    if (!on_boundary[node] && fits[node].size() > 0) {
      evaluate(node, at(node), out);
      continue;
    }
    std::vector<int> neighbours;
    for (int cell : patch[node])
      for (int other : space.cell_scalar_dofs(cell))
        if (!on_boundary[other] && fits[other].size() > 0) neighbours.push_back(other);
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
    if (neighbours.empty() && fits[node].size() > 0) neighbours.push_back(node);
    if (neighbours.empty()) {
      std::copy(averaged.begin() + size_t(node) * width, averaged.begin() + size_t(node + 1) * width, out);
      continue;
    }
    for (int other : neighbours) {
      evaluate(other, at(node), value.data());
      for (int a = 0; a < width; ++a) out[a] += value[a] / double(neighbours.size());
    }
  }
  return recovered;
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
  double sum = 0;
  for (int b = 0; b < (measure == GradientMeasure::Strain ? 1 : blocks); ++b) {
    const Eigen::Map<const Eigen::VectorXd> x(q + b * n, n);
    sum += x.dot(W * x);
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

SpaceErrorField recovery_error_estimate(const std::string& field, const FESpace& space,
                                        const Eigen::VectorXd& coefficients, GradientMeasure measure,
                                        const Eigen::MatrixXd& weight) {
  const Mesh& mesh = space.mesh();
  const int dim = mesh.dim(), components = space.num_components();
  const int measured_width = check_measure("space error estimate of '" + field + "'", space, coefficients, measure, weight);
  const int width = components * dim;
  const std::vector<double> nodal = space.order() == 1 ? patch_recovered_nodal_gradients(space, coefficients)
                                                        : averaged_nodal_gradients(space, coefficients);
  const ReferenceElement& element = space.element();
  // Degree 2p: the squared difference of two gradients of the space's degree p - 1 (p on a Q cell's
  // coordinates) is integrated exactly on simplices, well enough elsewhere.
  const RegionGeometry geometry(mesh, "all", 2 * space.order());
  const auto& points = geometry.reference_points(-1);
  std::vector<double> N(element.num_dofs()), dN(size_t(element.num_dofs()) * dim);
  std::vector<double> discrete(width), recovered(width), q_discrete(measured_width), q_recovered(measured_width);

  SpaceErrorField result;
  result.field = field;
  result.cells.assign(mesh.num_cells(), 0.0);
  double estimate_squared = 0, norm_squared = 0;
  for (int e = 0; e < geometry.num_elements(); ++e) {
    const int cell = geometry.cell(e);
    if (!space.has_cell(cell)) continue;
    const auto dofs = space.cell_scalar_dofs(cell);
    double cell_squared = 0;
    for (int q = 0; q < geometry.num_points(); ++q) {
      const double* xi = points[q].data();
      element.gradients(xi, dN.data());
      const double* G = geometry.inverse_jacobian_t(e, q);
      element.values(xi, N.data());
      std::fill(discrete.begin(), discrete.end(), 0.0);
      std::fill(recovered.begin(), recovered.end(), 0.0);
      for (size_t i = 0; i < dofs.size(); ++i) {
        for (int c = 0; c < components; ++c) {
          const double value = coefficients[space.dof(dofs[i], c)];
          for (int d = 0; d < dim; ++d) {
            double g = 0;
            for (int k = 0; k < dim; ++k) g += G[d * dim + k] * dN[i * dim + k];
            discrete[c * dim + d] += g * value;
          }
        }
        for (int a = 0; a < width; ++a) recovered[a] += N[i] * nodal[size_t(dofs[i]) * width + a];
      }
      measured(measure, dim, components, discrete.data(), q_discrete.data());
      measured(measure, dim, components, recovered.data(), q_recovered.data());
      norm_squared += geometry.weight(e, q) * weighted_square(measure, weight, components, q_discrete.data());
      for (int a = 0; a < measured_width; ++a) q_recovered[a] -= q_discrete[a];
      cell_squared += geometry.weight(e, q) * weighted_square(measure, weight, components, q_recovered.data());
    }
    result.cells[cell] = std::sqrt(std::max(cell_squared, 0.0));
    estimate_squared += cell_squared;
  }
  result.estimate = std::sqrt(std::max(estimate_squared, 0.0));
  result.norm = std::sqrt(std::max(norm_squared, 0.0));
  return result;
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
