// The engine alone, without the Model: assemble and solve -lap u = f on the unit square with u = g on
// the boundary, and report the error against the exact solution. This is the README's engine example.
//
//   build/release/examples/poisson [cells per side] [order]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "assembly/dof_layout.hpp"
#include "assembly/linear_solver.hpp"
#include "assembly/mesh_generators.hpp"
#include "assembly/norms.hpp"
#include "assembly/pointwise_term.hpp"
#include "assembly/system_matrix.hpp"
#include "assembly/term_assembly.hpp"

using namespace pc;

// u = sin(pi x) exp(y), so f = -lap u = (pi^2 - 1) u.
double exact(const double* x) { return std::sin(M_PI * x[0]) * std::exp(x[1]); }

// The weak form in flux form: R(w) = integral of grad u . grad w - f w. The tangent comes from Dual numbers.
// [snippet poisson]
struct Poisson {
  template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    out.f0[0][0] = -(M_PI * M_PI - 1) * exact(in.x);
    for (int d = 0; d < in.dim; ++d) out.f1[0][0][d] = in.grad[0][0][d];
  }
};

// [snippet poisson end]
int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 32;
  const int order = argc > 2 ? std::atoi(argv[2]) : 2;
  try {
    // [snippet poisson]
    auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, n, n, Shape::Triangle));
    FESpace space(mesh, order, 1);

    // One term, tested and differentiated with respect to its only field "u".
    auto term = std::make_shared<PointwiseTerm<Poisson>>("poisson", Integration::Cells,
                                                         std::vector<FieldUse>{{"u", /*gradient=*/true}},
                                                         std::vector<int>{0}, std::vector<Coupling>{{0, 0}}, Poisson{});
    TermAssembly assembly(term, "all", {&space});  // the pattern and slot maps, once
    // [snippet poisson end]

    // Dirichlet dofs are eliminated: they get no global index, and hold the boundary values.
    const std::vector<int> boundary = space.dofs_on("boundary");
    DofLayout layout;
    layout.add_field("u", space.num_dofs(), boundary);
    SystemMatrix matrix(layout);
    const int block = matrix.declare(0, 0, assembly.block(0));
    matrix.finalize();

    Eigen::VectorXd u = Eigen::VectorXd::Zero(space.num_dofs());
    for (int d : boundary) u[d] = exact(space.scalar_dof_point(d).data());

    // One Newton step solves the linear problem: J du = -R(u).
    Eigen::VectorXd residual = Eigen::VectorXd::Zero(space.num_dofs());
    const Eigen::VectorXd* values[] = {&u};
    Eigen::VectorXd* residuals[] = {&residual};
    assembly.assemble(values, 0.0, residuals, /*tangent=*/true);
    matrix.add(block, assembly.block(0));
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(layout.size());
    layout.add_to_global(0, residual, rhs);
    auto solver = make_linear_solver("umfpack");
    layout.add_from_global(0, solver->solve_once(matrix.matrix(), -rhs), u);

    const double error = l2_error(space, u, [](const double* x, double* out) { out[0] = exact(x); });
    std::printf("Poisson, P%d on %d x %d triangles: %d dofs, L2 error %.3e\n", order, n, n, space.num_dofs(), error);
    return 0;
  } catch (const Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
