#include "bricks/strain_stiffness_term.hpp"

#include <utility>
#include <vector>

#include "bricks/operator_matrices.hpp"
#include "bricks/voigt.hpp"

namespace pc {
namespace {

std::vector<FieldUse> fields_of(const std::string& test, const std::string& trial) {
  if (test == trial) return {{test, true}};
  return {{test, true}, {trial, true}};
}

}  // namespace

StrainStiffnessTerm::StrainStiffnessTerm(std::string name, const std::string& test, const std::string& trial,
                                         std::string datum, const Eigen::MatrixXd& C)
    : Term(std::move(name), Integration::Cells, fields_of(test, trial), {0}, {{0, test == trial ? 0 : 1}}),
      datum_(std::move(datum)),
      C_(C),
      dim_(stiffness_dimension(datum_, C)) {}

void StrainStiffnessTerm::assemble(const ElementData& e, LocalSystem& local, bool want_residual,
                                   bool want_tangent) const {
  const int trial = couplings()[0].trial;
  if (trial == 0)
    require_element_fits(*this, e, datum_, dim_, {true});
  else
    require_element_fits(*this, e, datum_, dim_, {true, true});
  const ElementData::Field& w = e.fields[0];
  const ElementData::Field& x = e.fields[trial];
  const int n = voigt_size(dim_);
  OperatorMatrix Bw, Bx;
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1> eps(n);
  for (int q = 0; q < e.num_points; ++q) {
    strain_matrix(w, q, dim_, Bw);
    if (want_residual) {
      strain_from_gradient(dim_, x.grad.data() + q * dim_ * dim_, eps.data());
      local.residual[0].noalias() += (e.weights[q] * Bw.transpose()) * (C_ * eps);
    }
    if (want_tangent) {
      if (trial != 0) strain_matrix(x, q, dim_, Bx);
      local.tangent[0].noalias() += (e.weights[q] * Bw.transpose()) * (C_ * (trial == 0 ? Bw : Bx));
    }
  }
}

}  // namespace pc
