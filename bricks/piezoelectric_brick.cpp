#include "bricks/piezoelectric_brick.hpp"

#include <utility>

#include "assembly/error.hpp"
#include "bricks/operator_matrices.hpp"
#include "bricks/voigt.hpp"

namespace pc {
namespace {

class PiezoelectricTerm : public Term {
 public:
  static constexpr int kV = 0, kPhi = 1, kU = 2;  // field indices

  PiezoelectricTerm(std::string name, const std::string& velocity, const std::string& potential,
                    const std::string& displacement, std::string datum, const Eigen::MatrixXd& E)
      : Term(std::move(name), Integration::Cells, {{velocity, true}, {potential, true}, {displacement, true}},
             {kV, kPhi}, {{kV, kPhi}, {kPhi, kU}}),
        datum_(std::move(datum)),
        E_(E),
        dim_(piezoelectric_dimension(datum_, E)) {}

  void assemble(const ElementData& e, LocalSystem& local, bool want_residual, bool want_tangent) const override {
    require_element_fits(*this, e, datum_, dim_, {true, false, true});
    const ElementData::Field& v = e.fields[kV];
    const ElementData::Field& phi = e.fields[kPhi];
    const ElementData::Field& u = e.fields[kU];
    const int n = voigt_size(dim_);
    OperatorMatrix Bv, Bu, G;
    Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1> eps(n);
    for (int q = 0; q < e.num_points; ++q) {
      const double w = e.weights[q];
      strain_matrix(v, q, dim_, Bv);
      gradient_matrix(phi, q, dim_, G);
      if (want_residual) {
        const Eigen::Map<const Eigen::VectorXd> grad_phi(phi.grad.data() + q * dim_, dim_);
        strain_from_gradient(dim_, u.grad.data() + q * dim_ * dim_, eps.data());
        local.residual[0].noalias() += (w * Bv.transpose()) * (E_.transpose() * grad_phi);
        local.residual[1].noalias() -= (w * G.transpose()) * (E_ * eps);
      }
      if (want_tangent) {
        strain_matrix(u, q, dim_, Bu);
        local.tangent[0].noalias() += (w * Bv.transpose()) * (E_.transpose() * G);
        local.tangent[1].noalias() -= (w * G.transpose()) * (E_ * Bu);
      }
    }
  }

 private:
  std::string datum_;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, 3, 6> E_;
  int dim_;
};

}  // namespace

PiezoelectricCouplingBrick::PiezoelectricCouplingBrick(std::string region, std::string datum, std::string velocity,
                                                       std::string potential, std::string displacement)
    : MaterialBrick("piezoelectric coupling", std::move(region), std::move(datum), false),
      velocity_(std::move(velocity)),
      potential_(std::move(potential)),
      displacement_(std::move(displacement)) {}

std::shared_ptr<const Term> PiezoelectricCouplingBrick::make_term(const Eigen::MatrixXd& E) const {
  check_piezoelectric(datum(), E, piezoelectric_dimension(datum(), E));
  return std::make_shared<const PiezoelectricTerm>(name(), velocity_, potential_, displacement_, datum(), E);
}

}  // namespace pc
