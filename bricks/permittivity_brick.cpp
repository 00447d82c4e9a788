#include "bricks/permittivity_brick.hpp"

#include <utility>

#include "assembly/error.hpp"
#include "bricks/operator_matrices.hpp"
#include "bricks/voigt.hpp"

namespace pc {
namespace {

// beta grad phi . grad psi for one scalar field.
class PermittivityTerm : public Term {
 public:
  PermittivityTerm(std::string name, const std::string& potential, std::string datum, const Eigen::MatrixXd& beta)
      : Term(std::move(name), Integration::Cells, {{potential, true}}, {0}, {{0, 0}}),
        datum_(std::move(datum)),
        beta_(beta),
        dim_(permittivity_dimension(datum_, beta)) {}

  void assemble(const ElementData& e, LocalSystem& local, bool want_residual, bool want_tangent) const override {
    require_element_fits(*this, e, datum_, dim_, {false});
    const ElementData::Field& phi = e.fields[0];
    OperatorMatrix G;
    for (int q = 0; q < e.num_points; ++q) {
      gradient_matrix(phi, q, dim_, G);
      if (want_residual) {
        const Eigen::Map<const Eigen::VectorXd> grad(phi.grad.data() + q * dim_, dim_);
        local.residual[0].noalias() += (e.weights[q] * G.transpose()) * (beta_ * grad);
      }
      if (want_tangent) local.tangent[0].noalias() += (e.weights[q] * G.transpose()) * (beta_ * G);
    }
  }

 private:
  std::string datum_;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, 3, 3> beta_;
  int dim_;
};

}  // namespace

PermittivityBrick::PermittivityBrick(std::string region, std::string datum, std::string potential)
    : MaterialBrick("permittivity", std::move(region), std::move(datum), true), potential_(std::move(potential)) {}

std::shared_ptr<const Term> PermittivityBrick::make_term(const Eigen::MatrixXd& beta) const {
  check_permittivity(datum(), beta, permittivity_dimension(datum(), beta));
  return std::make_shared<const PermittivityTerm>(name(), potential_, datum(), beta);
}

}  // namespace pc
