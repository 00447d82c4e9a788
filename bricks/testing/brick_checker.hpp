#pragma once
// A harness that checks any brick alone on a small mesh, in the spirit of GetFEM's
// check_stiffness_matrix_and_rhs: its tangent against central finite differences of its residual at
// random states (each column at the steps fd_step * {0.1, 1, 10, 100}, keeping the best, and not counting
// differences below the round-off 8 eps_mach |R| / h of a step), its `linear` claim (R(x) = K x + R(0) exactly), its
// `symmetric` claim (K = K^T), and finite residuals and tangents at extreme states. Usable from GoogleTest:
//
//   BrickCheckSetup setup = BrickCheckSetup::square(Shape::Triangle, 1);  // fields v (2 comp.), phi, ...
//   auto report = check_brick(my_brick, my_data, setup);
//   EXPECT_TRUE(report.ok()) << report;
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "assembly/fe_space.hpp"
#include "assembly/parameters.hpp"
#include "bricks/brick.hpp"

namespace pc {

// Named constants for bricks under test (a DataView backed by a map).
class ConstantTable : public DataView {
 public:
  ConstantTable& set(const std::string& name, Eigen::MatrixXd value);
  ConstantTable& set(const std::string& name, double value);
  // Scalars by name, e.g. a law's parameters: set(law_values(LinearDampedResponse{1e12})).
  ConstantTable& set(const ParameterValues& values);
  const Eigen::MatrixXd& constant(const std::string& name) const override;

 private:
  std::map<std::string, Eigen::MatrixXd> values_;
};

struct BrickCheckSetup {
  std::shared_ptr<const Mesh> mesh;
  // The space of every field a brick may name (unknowns, affine and data fields alike).
  std::map<std::string, std::shared_ptr<const FESpace>> spaces;
  // Affine fields and the unknown whose columns their tangents fill in a Model (u = k v + u_prev fills
  // v's columns): the symmetry check compares blocks after this mapping.
  std::map<std::string, std::string> affine_base = {{"u", "v"}, {"a", "v"}};
  // Random states draw each field's coefficients uniformly from [low, high] (default [-1, 1]).
  std::map<std::string, std::pair<double, double>> ranges;
  int samples = 3;
  unsigned seed = 12345;
  double fd_step = 1e-6;  // relative to the magnitude of the perturbed coefficient (at least 1)
  // On max(0, |K e_j - FD_j| - 8 eps_mach |R| / h) / max(|FD_j|, |K e_j|), the best over the steps.
  double fd_tolerance = 1e-6;
  double linear_tolerance = 1e-10;
  double symmetry_tolerance = 1e-12;
  std::vector<double> extreme_scales = {1e-12, 1e6, 1e12};  // states scaled by these must stay finite

  // The unit square (2D) meshed with 2 x 2 cells of the given shape, with regions "all", "boundary",
  // "left", "right", "bottom", "top", and the spaces v, u, a, v_prev, u_prev (vector) and phi, phi_prev
  // (scalar) of the given order.
  static BrickCheckSetup square(Shape shape = Shape::Triangle, int order = 1);
  // The unit cube meshed with 1 x 1 x 1 cells (split into tetrahedra, or one hexahedron), same fields,
  // regions xmin ... zmax.
  static BrickCheckSetup cube(Shape shape = Shape::Tetrahedron, int order = 1);
};

struct BrickCheckReport {
  std::string brick;
  double max_tangent_error = 0;  // worst relative tangent-vs-FD error over samples and couplings
  double max_linear_error = 0;
  double max_symmetry_error = 0;
  int tangent_checks = 0;
  std::vector<std::string> failures;
  bool ok() const { return failures.empty(); }
};
std::ostream& operator<<(std::ostream& out, const BrickCheckReport& report);

// Runs every check the brick's claims call for. The brick is updated from `data` first.
BrickCheckReport check_brick(Brick& brick, const DataView& data, const BrickCheckSetup& setup);

}  // namespace pc
