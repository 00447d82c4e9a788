#include "models/output/piezo_fields.hpp"

#include <array>
#include <cmath>

#include <Eigen/LU>

#include "assembly/cell_geometry.hpp"
#include "assembly/error.hpp"
#include "bricks/voigt.hpp"

namespace pc {
namespace {

using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using SmallMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor, 3, 3>;

// The centroid of a reference cell is the mean of its vertices.
std::array<double, 3> reference_centroid(Shape shape) {
  std::array<double, 3> centroid{};
  for (int k = 0; k < num_vertices(shape); ++k) {
    const auto vertex = reference_vertex(shape, k);
    for (int d = 0; d < 3; ++d) centroid[d] += vertex[d] / num_vertices(shape);
  }
  return centroid;
}

// Physical gradient of every component of a field at each cell's centroid:
// grad[(cell * components + c) * dim + d] = d f_c / d x_d, zero in cells outside the field's space.
std::vector<double> centroid_gradients(const Model& model, const std::string& name) {
  const FESpace& space = model.space(name);
  const Eigen::VectorXd& coefficients = model.values(name);
  const Mesh& mesh = space.mesh();
  const int dim = mesh.dim();
  const int components = space.num_components();
  const ReferenceElement& element = space.element();
  const auto xi = reference_centroid(mesh.cell_shape());
  // Reference gradients at the centroid are the same in every cell.
  std::vector<double> dN(size_t(element.num_dofs()) * dim);
  element.gradients(xi.data(), dN.data());
  const Eigen::Map<const RowMajorMatrix> reference_gradients(dN.data(), element.num_dofs(), dim);

  std::vector<double> grad(size_t(mesh.num_cells()) * components * dim, 0.0);
  for (int cell = 0; cell < mesh.num_cells(); ++cell) {
    if (!space.has_cell(cell)) continue;
    double J[9];
    cell_jacobian(mesh, cell, xi.data(), J);
    const auto dofs = space.cell_scalar_dofs(cell);
    SmallMatrix reference_gradient = SmallMatrix::Zero(components, dim);  // d f_c / d xi_j
    for (int i = 0; i < element.num_dofs(); ++i)
      for (int c = 0; c < components; ++c)
        reference_gradient.row(c) += coefficients[space.dof(dofs[i], c)] * reference_gradients.row(i);
    // d f / d x = (d f / d xi) (d xi / d x) = (d f / d xi) J^{-1}.
    Eigen::Map<RowMajorMatrix>(grad.data() + size_t(cell) * components * dim, components, dim) =
        reference_gradient * Eigen::Map<const RowMajorMatrix>(J, dim, dim).inverse();
  }
  return grad;
}

void require_components(const Model& model, const std::string& name, int components, const char* what) {
  const int actual = model.space(name).num_components();
  require(actual == components, what, ": field '", name, "' has ", actual, " components, expected ", components);
}

// The tensor of the term tensor * field: null without the field, or without an optional constant;
// otherwise the model's constant, which must exist and have the shape rows x cols.
const Eigen::MatrixXd* term_tensor(const Model& model, const std::string& field, const char* constant,
                                   const char* what, int rows, int cols, bool optional = false) {
  if (!model.has_field(field) || (optional && !model.has_constant(constant))) return nullptr;
  require(model.has_constant(constant), "piezo output: field '", field, "' needs the constant '", constant, "' (",
          what, "), which the model does not have");
  const Eigen::MatrixXd& tensor = model.constant(constant);
  require(tensor.rows() == rows && tensor.cols() == cols, "piezo output: constant '", constant, "' (", what,
          ") is ", tensor.rows(), " x ", tensor.cols(), ", a ", model.mesh().dim(), "D model needs ", rows, " x ",
          cols);
  return &tensor;
}

// Per cell: out_c += scale * tensor * in_c, with in and out stored cell after cell.
void add_product(const Eigen::MatrixXd& tensor, const std::vector<double>& in, double scale, std::vector<double>& out) {
  const Eigen::Index cells = Eigen::Index(out.size()) / tensor.rows();
  Eigen::Map<Eigen::MatrixXd>(out.data(), tensor.rows(), cells) +=
      scale * tensor * Eigen::Map<const Eigen::MatrixXd>(in.data(), tensor.cols(), cells);
}

// grad phi per cell (num_cells * dim values).
std::vector<double> potential_gradient(const Model& model, const std::string& potential) {
  require_components(model, potential, 1, "electric field");
  return centroid_gradients(model, potential);
}

}  // namespace

std::vector<double> cell_strain(const Model& model, const std::string& displacement) {
  const int dim = model.mesh().dim();
  require_components(model, displacement, dim, "cell_strain");
  const std::vector<double> grad = centroid_gradients(model, displacement);
  const int n = voigt_size(dim);
  std::vector<double> strain(size_t(model.mesh().num_cells()) * n);
  for (int cell = 0; cell < model.mesh().num_cells(); ++cell)
    strain_from_gradient(dim, grad.data() + size_t(cell) * dim * dim, strain.data() + size_t(cell) * n);
  return strain;
}

std::vector<double> cell_stress(const Model& model, const PiezoFieldNames& names) {
  const int dim = model.mesh().dim();
  const int n = voigt_size(dim);
  std::vector<double> stress(size_t(model.mesh().num_cells()) * n, 0.0);
  if (const auto* A = term_tensor(model, names.velocity, "A", "viscosity", n, n, /*optional=*/true))
    add_product(*A, cell_strain(model, names.velocity), 1, stress);
  if (const auto* B = term_tensor(model, names.displacement, "B", "elasticity", n, n))
    add_product(*B, cell_strain(model, names.displacement), 1, stress);
  if (const auto* E = term_tensor(model, names.potential, "E", "piezoelectric", dim, n))
    add_product(E->transpose(), potential_gradient(model, names.potential), 1, stress);
  return stress;
}

std::vector<double> cell_electric_field(const Model& model, const std::string& potential) {
  std::vector<double> field = potential_gradient(model, potential);
  for (double& value : field) value = -value;
  return field;
}

std::vector<double> cell_electric_displacement(const Model& model, const PiezoFieldNames& names) {
  const int dim = model.mesh().dim();
  const int n = voigt_size(dim);
  std::vector<double> displacement(size_t(model.mesh().num_cells()) * dim, 0.0);
  if (const auto* E = term_tensor(model, names.displacement, "E", "piezoelectric", dim, n))
    add_product(*E, cell_strain(model, names.displacement), 1, displacement);
  if (const auto* beta = term_tensor(model, names.potential, "beta", "permittivity", dim, dim))
    add_product(*beta, potential_gradient(model, names.potential), -1, displacement);
  return displacement;
}

double von_mises(std::span<const double> s, int dim) {
  require(s.size() == size_t(voigt_size(dim)), "von_mises: a ", dim, "D Voigt stress has ", voigt_size(dim),
          " values, got ", s.size());
  if (dim == 2) return std::sqrt(s[0] * s[0] - s[0] * s[1] + s[1] * s[1] + 3 * s[2] * s[2]);
  const double normal = (s[0] - s[1]) * (s[0] - s[1]) + (s[1] - s[2]) * (s[1] - s[2]) + (s[2] - s[0]) * (s[2] - s[0]);
  return std::sqrt(normal / 2 + 3 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

void add_piezo_output(VtuWriter& writer, const Model& model, const PiezoFieldNames& names,
                      const std::function<bool(const std::string&)>& wanted) {
  const auto want = [&](const std::string& name) { return !wanted || wanted(name); };
  const int dim = model.mesh().dim();
  const int n = voigt_size(dim);
  for (const std::string& name : {names.velocity, names.displacement, names.potential})
    if (model.has_field(name) && want(name)) writer.add_point_field(name, model.space(name), model.values(name));

  const bool mechanical = model.has_field(names.displacement) || model.has_field(names.velocity);
  if (model.has_field(names.displacement) && want("strain"))
    writer.add_cell_data("strain", n, cell_strain(model, names.displacement));
  if (mechanical && (want("stress") || want("von_mises"))) {
    std::vector<double> stress = cell_stress(model, names);
    std::vector<double> equivalent(size_t(model.mesh().num_cells()));
    for (size_t cell = 0; cell < equivalent.size(); ++cell)
      equivalent[cell] = von_mises(std::span<const double>(stress).subspan(cell * n, n), dim);
    if (want("stress")) writer.add_cell_data("stress", n, std::move(stress));
    if (want("von_mises")) writer.add_cell_data("von_mises", 1, std::move(equivalent));
  }
  if (model.has_field(names.potential)) {
    if (want("electric_field")) writer.add_cell_data("electric_field", dim, cell_electric_field(model, names.potential));
    if (want("electric_displacement"))
      writer.add_cell_data("electric_displacement", dim, cell_electric_displacement(model, names));
  }
}

}  // namespace pc
