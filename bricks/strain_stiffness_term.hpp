#pragma once
// The bilinear form C eps(x) : eps(w) of a vector field x tested with a vector field w, C in Voigt form:
// Kelvin-Voigt viscosity (x = w = v) and elasticity (x = u, w = v) share it. Written by hand with Voigt
// strain matrices because it is assembled over every cell of the body. Its quadrature degree stays at
// Term's default 2 * order although simplices need only 2 * (order - 1): a term sees the order but not
// the cell shape, and quadrilaterals and hexahedra would be under-integrated (hourglass modes).
#include <string>

#include <Eigen/Core>

#include "assembly/term.hpp"

namespace pc {

class StrainStiffnessTerm : public Term {
 public:
  // test == trial gives the single field `test` and the coupling (test, test); otherwise the fields are
  // {test, trial} with the coupling (test, trial). `datum` names C in error messages; C must have been
  // checked (check_stiffness).
  StrainStiffnessTerm(std::string name, const std::string& test, const std::string& trial, std::string datum,
                      const Eigen::MatrixXd& C);

  void assemble(const ElementData& e, LocalSystem& local, bool want_residual, bool want_tangent) const override;

 private:
  std::string datum_;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, 6, 6> C_;
  int dim_;
};

}  // namespace pc
