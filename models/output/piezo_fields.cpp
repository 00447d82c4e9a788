#include "models/output/piezo_fields.hpp"

#include <array>
#include <cmath>
#include <map>
#include <optional>

#include <Eigen/LU>

#include "assembly/cell_geometry.hpp"
#include "assembly/error.hpp"
#include "bricks/voigt.hpp"

namespace pc {
namespace {

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
// Fixed-size matrices: a dynamic-size inverse would factorise and allocate in every cell.
template <int Dim> std::vector<double> centroid_gradients(const FESpace& space, const Eigen::VectorXd& coefficients) {
  using Jacobian = Eigen::Matrix<double, Dim, Dim, Eigen::RowMajor>;
  using Row = Eigen::Matrix<double, 1, Dim>;
  const Mesh& mesh = space.mesh();
  const int components = space.num_components();
  const ReferenceElement& element = space.element();
  const auto xi = reference_centroid(mesh.cell_shape());
  // Reference gradients at the centroid are the same in every cell: dN[i * Dim + j] = d N_i / d xi_j.
  std::vector<double> dN(size_t(element.num_dofs()) * Dim);
  element.gradients(xi.data(), dN.data());

  std::vector<double> grad(size_t(mesh.num_cells()) * components * Dim, 0.0);
  for (int cell = 0; cell < mesh.num_cells(); ++cell) {
    if (!space.has_cell(cell)) continue;
    Jacobian J;
    cell_jacobian(mesh, cell, xi.data(), J.data());
    const Jacobian inverse = J.inverse();
    const auto dofs = space.cell_scalar_dofs(cell);
    for (int c = 0; c < components; ++c) {
      Row reference = Row::Zero();  // d f_c / d xi
      for (size_t i = 0; i < dofs.size(); ++i)
        reference += coefficients[space.dof(dofs[i], c)] * Eigen::Map<const Row>(dN.data() + i * Dim);
      // d f / d x = (d f / d xi) (d xi / d x) = (d f / d xi) J^{-1}.
      Eigen::Map<Row>(grad.data() + (size_t(cell) * components + c) * Dim) = reference * inverse;
    }
  }
  return grad;
}

std::vector<double> centroid_gradients(const Model& model, const std::string& name) {
  const FESpace& space = model.space(name);
  switch (space.mesh().dim()) {
    case 1: return centroid_gradients<1>(space, model.values(name));
    case 2: return centroid_gradients<2>(space, model.values(name));
    default: return centroid_gradients<3>(space, model.values(name));
  }
}

void require_components(const Model& model, const std::string& name, int components, const char* what) {
  const int actual = model.space(name).num_components();
  require(actual == components, what, ": field '", name, "' has ", actual, " components, expected ", components);
}

// The tensor of the term tensor * field: null without the field, or without an optional constant;
// otherwise the model's constant, which must exist and have the shape rows x cols.
const Eigen::MatrixXd* term_tensor(const Model& model, const std::string& field, const char* constant, const char* what,
                                   int rows, int cols, bool optional = false) {
  if (!model.has_field(field) || (optional && !model.has_constant(constant))) return nullptr;
  require(model.has_constant(constant), "piezo output: field '", field, "' needs the constant '", constant, "' (", what,
          "), which the model does not have");
  const Eigen::MatrixXd& tensor = model.constant(constant);
  require(tensor.rows() == rows && tensor.cols() == cols, "piezo output: constant '", constant, "' (", what, ") is ",
          tensor.rows(), " x ", tensor.cols(), ", a ", model.mesh().dim(), "D model needs ", rows, " x ", cols);
  return &tensor;
}

// Per cell: out_c += scale * tensor * in_c, with in and out stored cell after cell.
void add_product(const Eigen::MatrixXd& tensor, const std::vector<double>& in, double scale, std::vector<double>& out) {
  const Eigen::Index cells = Eigen::Index(out.size()) / tensor.rows();
  Eigen::Map<Eigen::MatrixXd>(out.data(), tensor.rows(), cells) +=
      scale * tensor * Eigen::Map<const Eigen::MatrixXd>(in.data(), tensor.cols(), cells);
}

std::vector<double> negated(std::vector<double> values) {
  for (double& value : values) value = -value;
  return values;
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

namespace {

// A model's cell strains and potential gradient, each computed on first use and kept, so that the arrays
// of one output that need the same one share it.
class CellGradients {
 public:
  CellGradients(const Model& model, const PiezoFieldNames& names) : model_(model), names_(names) {}

  const std::vector<double>& strain(const std::string& field) {
    const auto [at, added] = strains_.try_emplace(field);
    if (added) at->second = cell_strain(model_, field);
    return at->second;
  }
  const std::vector<double>& potential_gradient() {
    if (!potential_gradient_) potential_gradient_ = pc::potential_gradient(model_, names_.potential);
    return *potential_gradient_;
  }

 private:
  const Model& model_;
  const PiezoFieldNames& names_;
  std::map<std::string, std::vector<double>> strains_;
  std::optional<std::vector<double>> potential_gradient_;
};

std::vector<double> stress(const Model& model, const PiezoFieldNames& names, CellGradients& gradients) {
  const int dim = model.mesh().dim();
  const int n = voigt_size(dim);
  std::vector<double> stress(size_t(model.mesh().num_cells()) * n, 0.0);
  if (const auto* A = term_tensor(model, names.velocity, "A", "viscosity", n, n, /*optional=*/true))
    add_product(*A, gradients.strain(names.velocity), 1, stress);
  if (const auto* B = term_tensor(model, names.displacement, "B", "elasticity", n, n))
    add_product(*B, gradients.strain(names.displacement), 1, stress);
  if (const auto* E = term_tensor(model, names.potential, "E", "piezoelectric", dim, n))
    add_product(E->transpose(), gradients.potential_gradient(), 1, stress);
  return stress;
}

std::vector<double> electric_displacement(const Model& model, const PiezoFieldNames& names, CellGradients& gradients) {
  const int dim = model.mesh().dim();
  const int n = voigt_size(dim);
  std::vector<double> displacement(size_t(model.mesh().num_cells()) * dim, 0.0);
  if (const auto* E = term_tensor(model, names.displacement, "E", "piezoelectric", dim, n))
    add_product(*E, gradients.strain(names.displacement), 1, displacement);
  if (const auto* beta = term_tensor(model, names.potential, "beta", "permittivity", dim, dim))
    add_product(*beta, gradients.potential_gradient(), -1, displacement);
  return displacement;
}

}  // namespace

std::vector<double> cell_stress(const Model& model, const PiezoFieldNames& names) {
  CellGradients gradients(model, names);
  return stress(model, names, gradients);
}

std::vector<double> cell_electric_field(const Model& model, const std::string& potential) {
  return negated(potential_gradient(model, potential));
}

std::vector<double> cell_electric_displacement(const Model& model, const PiezoFieldNames& names) {
  CellGradients gradients(model, names);
  return electric_displacement(model, names, gradients);
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

  CellGradients gradients(model, names);
  if (model.has_field(names.displacement) && want("strain"))
    writer.add_cell_data("strain", n, gradients.strain(names.displacement));
  const bool mechanical = model.has_field(names.displacement) || model.has_field(names.velocity);
  if (mechanical && (want("stress") || want("von_mises"))) {
    std::vector<double> sigma = stress(model, names, gradients);
    std::vector<double> equivalent(size_t(model.mesh().num_cells()));
    for (size_t cell = 0; cell < equivalent.size(); ++cell)
      equivalent[cell] = von_mises(std::span<const double>(sigma).subspan(cell * n, n), dim);
    if (want("stress")) writer.add_cell_data("stress", n, std::move(sigma));
    if (want("von_mises")) writer.add_cell_data("von_mises", 1, std::move(equivalent));
  }
  if (model.has_field(names.potential)) {
    if (want("electric_field")) writer.add_cell_data("electric_field", dim, negated(gradients.potential_gradient()));
    if (want("electric_displacement"))
      writer.add_cell_data("electric_displacement", dim, electric_displacement(model, names, gradients));
  }
}

}  // namespace pc
