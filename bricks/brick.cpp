#include "bricks/brick.hpp"

#include "assembly/error.hpp"

namespace pc {

double DataView::scalar(const std::string& name) const {
  const Eigen::MatrixXd& m = constant(name);
  require(m.size() == 1, "datum '", name, "' is a ", m.rows(), " x ", m.cols(), " matrix, not a scalar");
  return m(0, 0);
}

}  // namespace pc
