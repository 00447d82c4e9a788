#include "bricks/inertia_brick.hpp"

#include <cmath>
#include <utility>

#include "assembly/error.hpp"

namespace pc {
namespace {

// rho x . w for fields {w, x} of equal component counts: block-diagonal in the components.
class MassTerm : public Term {
 public:
  MassTerm(std::string name, const std::string& test, const std::string& trial, double rho)
      : Term(std::move(name), Integration::Cells, {{test, false}, {trial, false}}, {0}, {{0, 1}}), rho_(rho) {}

  void assemble(const ElementData& e, LocalSystem& local, bool want_residual, bool want_tangent) const override {
    const ElementData::Field& w = e.fields[0];
    const ElementData::Field& x = e.fields[1];
    const int nc = w.num_components;
    require(x.num_components == nc, "term '", name(), "': field '", fields()[1].name, "' has ", x.num_components,
            " components but '", fields()[0].name, "' has ", nc);
    for (int q = 0; q < e.num_points; ++q) {
      const double scale = rho_ * e.weights[q];
      for (int i = 0; i < w.num_shapes; ++i) {
        const double Ni = scale * w.shape(q, i);
        if (want_residual)
          for (int c = 0; c < nc; ++c) local.residual[0][i * nc + c] += Ni * x.value[q * nc + c];
        if (!want_tangent) continue;
        for (int j = 0; j < x.num_shapes; ++j) {
          const double m = Ni * x.shape(q, j);
          for (int c = 0; c < nc; ++c) local.tangent[0](i * nc + c, j * nc + c) += m;
        }
      }
    }
  }

 private:
  double rho_;
};

}  // namespace

InertiaBrick::InertiaBrick(std::string region, std::string datum, std::string velocity, std::string acceleration)
    : MaterialBrick("inertia", std::move(region), std::move(datum), true),
      velocity_(std::move(velocity)),
      acceleration_(std::move(acceleration)) {}

std::shared_ptr<const Term> InertiaBrick::make_term(const Eigen::MatrixXd& constant) const {
  require(constant.size() == 1, "datum '", datum(), "' (density) must be a scalar, got a ", constant.rows(), " x ",
          constant.cols(), " matrix");
  const double rho = constant(0, 0);
  require(std::isfinite(rho) && rho > 0, "datum '", datum(), "' (density) must be > 0, got ", rho,
          "; for a quasi-static model leave out the inertia brick");
  return std::make_shared<const MassTerm>(name(), velocity_, acceleration_, rho);
}

}  // namespace pc
