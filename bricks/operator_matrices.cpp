#include "bricks/operator_matrices.hpp"

#include "assembly/error.hpp"
#include "bricks/voigt.hpp"

namespace pc {

void strain_matrix(const ElementData::Field& field, int q, int dim, OperatorMatrix& B) {
  require(field.num_shapes * dim <= kMaxOperatorColumns, "strain_matrix: ", field.num_shapes,
          " shape functions are more than the largest supported element has");
  const int n = voigt_size(dim);
  B.resize(n, field.num_shapes * dim);
  double Bi[6 * 3];
  for (int i = 0; i < field.num_shapes; ++i) {
    strain_displacement(dim, field.shape_grad(q, i, dim), Bi);
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < dim; ++c) B(r, i * dim + c) = Bi[r * dim + c];
  }
}

void gradient_matrix(const ElementData::Field& field, int q, int dim, OperatorMatrix& G) {
  require(field.num_shapes <= kMaxOperatorColumns, "gradient_matrix: ", field.num_shapes,
          " shape functions are more than the largest supported element has");
  G.resize(dim, field.num_shapes);
  for (int i = 0; i < field.num_shapes; ++i) {
    const double* g = field.shape_grad(q, i, dim);
    for (int d = 0; d < dim; ++d) G(d, i) = g[d];
  }
}

void require_element_fits(const Term& term, const ElementData& e, const std::string& datum, int tensor_dim,
                          std::initializer_list<bool> vector) {
  require(e.dim == tensor_dim, "term '", term.name(), "': datum '", datum, "' is written for ", tensor_dim,
          "D but the mesh is ", e.dim, "D");
  int f = 0;
  for (bool is_vector : vector) {
    const int expected = is_vector ? e.dim : 1;
    require(e.fields[f].num_components == expected, "term '", term.name(), "': field '", term.fields()[f].name,
            "' has ", e.fields[f].num_components, " components, expected ", expected);
    ++f;
  }
}

}  // namespace pc
