#include "models/modal_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include <Spectra/SymGEigsShiftSolver.h>

#include "assembly/error.hpp"
#include "assembly/linear_solver.hpp"
#include "assembly/processes.hpp"

namespace pc {
namespace {

// The model's linear Jacobian with the displacement's and the acceleration's factors set.
CsrMatrix linear_part(Model& model, const ModalOptions& o, double displacement_factor, double acceleration_factor) {
  model.set_affine(o.displacement, displacement_factor,
                   std::vector<double>(model.affine_coefficients(o.displacement).size(), 0.0));
  model.set_affine(o.acceleration, acceleration_factor,
                   std::vector<double>(model.affine_coefficients(o.acceleration).size(), 0.0));
  model.assemble(true);
  return model.linear_jacobian();
}

// y = (K - sigma M)^-1 x on the velocity's free dofs, through the saddle system with the potential.
class ShiftInvert {
 public:
  using Scalar = double;
  ShiftInvert(CsrMatrix stiffness, CsrMatrix mass, int mechanical, std::string solver)
      : stiffness_(std::move(stiffness)),
        mass_(std::move(mass)),
        mechanical_(mechanical),
        solver_(make_linear_solver(solver)) {}
  Eigen::Index rows() const { return mechanical_; }
  Eigen::Index cols() const { return mechanical_; }
  void set_shift(double sigma) {
    const CsrMatrix shifted = stiffness_ - sigma * mass_;
    solver_->analyze(shifted);
    solver_->factorize(shifted);
  }
  // The whole solution [x; y] for a mechanical right-hand side b.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const {
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(stiffness_.rows());
    rhs.head(mechanical_) = b;
    return solver_->solve(rhs);
  }
  void perform_op(const double* x, double* y) const {
    ++applications;
    y_ = solve(Eigen::Map<const Eigen::VectorXd>(x, mechanical_));
    std::copy_n(y_.data(), mechanical_, y);
  }
  mutable int applications = 0;

 private:
  CsrMatrix stiffness_, mass_;
  int mechanical_;
  std::unique_ptr<LinearSolver> solver_;
  mutable Eigen::VectorXd y_;
};

// y = M x on the velocity's free dofs.
struct MassProduct {
  using Scalar = double;
  const CsrMatrix* mass;
  int mechanical;
  Eigen::Index rows() const { return mechanical; }
  Eigen::Index cols() const { return mechanical; }
  void perform_op(const double* x, double* y) const {
    Eigen::Map<Eigen::VectorXd>(y, mechanical) =
        mass->topLeftCorner(mechanical, mechanical) * Eigen::Map<const Eigen::VectorXd>(x, mechanical);
  }
};

}  // namespace

ModalResult modal_analysis(Model& model, const ModalOptions& o) {
  require(model.finalized(), "modal analysis: finalize the model first");
  // Each process holds a share of the matrices; the shift-invert solves would need MUMPS on their sum.
  require(!processes::distributed(), "modal analysis: runs on one process (this run has ", processes::count(),
          "); run `piezocontact modes` without mpirun");
  require(o.modes >= 1, "modal analysis: modes must be >= 1, got ", o.modes);
  require(std::isfinite(o.shift_hz) && o.shift_hz >= 0, "modal analysis: shift_hz must be finite and >= 0, got ",
          o.shift_hz);
  for (const std::string& f : {o.displacement, o.acceleration})
    require(model.has_field(f) && model.field_kind(f) == FieldKind::Affine,
            "modal analysis: the model has no affine "
            "field '",
            f, "' (",
            f == o.acceleration ? "a mass needs an inertia brick and a scheme with the acceleration"
                                : "the time scheme makes it",
            ")");
  // The blocks in the layout's order (made by the first assembly); the velocity's must come first.
  model.assemble(false);
  const std::vector<ProblemBlock> blocks = model.blocks();
  require(!blocks.empty() && blocks[0].name == o.velocity && blocks[0].begin == 0, "modal analysis: the velocity '",
          o.velocity, "' must be the first unknown of the system");
  const int mechanical = blocks[0].size;
  const int n = int(model.free_values().size());
  const bool electric = blocks.size() > 1;
  require(blocks.size() <= 2 && (!electric || (blocks[1].name == o.potential && blocks[1].begin == mechanical)),
          "modal analysis: the system's unknowns must be the velocity '", o.velocity,
          "' and, optionally, the potential '", o.potential, "'");
  require(o.modes < mechanical, "modal analysis: ", o.modes, " modes asked of ", mechanical, " free velocity dofs");

  // Pick the matrices apart, then put the model back as it was.
  const double u_factor = model.affine_factor(o.displacement), a_factor = model.affine_factor(o.acceleration);
  const std::vector<double> u_history = model.affine_coefficients(o.displacement);
  const std::vector<double> a_history = model.affine_coefficients(o.acceleration);
  const CsrMatrix base = linear_part(model, o, 0, 0);            // damping A, and the potential's columns
  const CsrMatrix with_mass = linear_part(model, o, 0, 1);       // + M
  const CsrMatrix with_stiffness = linear_part(model, o, 1, 0);  // + K_uu and the potential's rows' -C
  model.set_affine(o.displacement, u_factor, u_history);
  model.set_affine(o.acceleration, a_factor, a_history);

  CsrMatrix mass = with_mass - base;
  mass.prune(0.0);
  // The stiffness: everything but the damping (the base's mechanical block).
  CsrMatrix damping = base;
  for (int r = 0; r < n; ++r)
    for (CsrMatrix::InnerIterator it(damping, r); it; ++it)
      if (r >= mechanical || it.col() >= mechanical) it.valueRef() = 0;
  CsrMatrix stiffness = with_stiffness - damping;
  // The electric rows' sign flipped: [[K_uu, C^T], [C, -P]], symmetric.
  for (int r = mechanical; r < n; ++r)
    for (CsrMatrix::InnerIterator it(stiffness, r); it; ++it) it.valueRef() = -it.value();
  auto largest = [](const CsrMatrix& a) {
    double m = 0;
    for (int k = 0; k < a.nonZeros(); ++k) m = std::max(m, std::abs(a.valuePtr()[k]));
    return m;
  };
  const double difference = largest(stiffness - CsrMatrix(stiffness.transpose())), size = largest(stiffness);
  require(difference <= 1e-9 * size,
          "modal analysis: the stiffness is not symmetric (a non-symmetric linear brick?), "
          "largest difference ",
          difference, " against entries of ", size);
  mass.conservativeResize(n, n);

  const double omega_shift = 2 * std::numbers::pi * o.shift_hz;
  ShiftInvert op(stiffness, mass, mechanical, o.linear_solver);
  MassProduct mass_product{&mass, mechanical};
  const int ncv = std::min(mechanical, std::max(2 * o.modes + 1, 20));
  Spectra::SymGEigsShiftSolver<ShiftInvert, MassProduct, Spectra::GEigsMode::ShiftInvert> eigs(
      op, mass_product, o.modes, ncv, omega_shift * omega_shift);
  eigs.init();
  eigs.compute(Spectra::SortRule::LargestMagn, 1000, 1e-12, Spectra::SortRule::SmallestAlge);
  require(eigs.info() == Spectra::CompInfo::Successful, "modal analysis: the Lanczos iteration did not converge to ",
          o.modes, " modes near ", o.shift_hz, " Hz in ", eigs.num_iterations(), " restarts");

  ModalResult result;
  result.lanczos_iterations = int(eigs.num_iterations());
  result.operator_applications = op.applications;
  const Eigen::VectorXd lambda = eigs.eigenvalues();
  const Eigen::MatrixXd shapes = eigs.eigenvectors();
  const DofLayout& layout = model.layout();
  const int v_index = layout.field_index(o.velocity);
  result.velocity_shapes = Eigen::MatrixXd::Zero(model.space(o.velocity).num_dofs(), o.modes);
  if (electric) result.potential_shapes = Eigen::MatrixXd::Zero(model.space(o.potential).num_dofs(), o.modes);
  for (int m = 0; m < o.modes; ++m) {
    require(lambda[m] > 0, "modal analysis: eigenvalue ", lambda[m], " of mode ", m,
            " is not positive (a body "
            "free to move rigidly, or a system that is not positive definite)");
    result.frequencies_hz.push_back(std::sqrt(lambda[m]) / (2 * std::numbers::pi));
    Eigen::VectorXd global = Eigen::VectorXd::Zero(n);
    global.head(mechanical) = shapes.col(m);
    if (electric) {
      // y = P^-1 C x: the saddle solve of (lambda - sigma) M x gives [x; y].
      Eigen::VectorXd mx(mechanical);
      mass_product.perform_op(shapes.col(m).data(), mx.data());
      global.tail(n - mechanical) = op.solve((lambda[m] - omega_shift * omega_shift) * mx).tail(n - mechanical);
      Eigen::VectorXd phi = Eigen::VectorXd::Zero(model.space(o.potential).num_dofs());
      layout.add_from_global(layout.field_index(o.potential), global, phi);
      result.potential_shapes.col(m) = phi;
    }
    Eigen::VectorXd v = Eigen::VectorXd::Zero(model.space(o.velocity).num_dofs());
    layout.add_from_global(v_index, global, v);
    result.velocity_shapes.col(m) = v;
  }
  return result;
}

}  // namespace pc
