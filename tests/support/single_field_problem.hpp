#pragma once
// Test support: one unknown field, a few terms, Dirichlet values by elimination, one Newton step
// (exact for linear problems). Written against the public engine API only, as a user would.
#include <memory>
#include <string>
#include <vector>

#include "assembly/dof_layout.hpp"
#include "assembly/fe_space.hpp"
#include "assembly/linear_solver.hpp"
#include "assembly/system_matrix.hpp"
#include "assembly/term_assembly.hpp"

namespace pc::testing {

struct SingleFieldProblem {
  const FESpace& space;
  std::vector<std::shared_ptr<const Term>> terms;  // each names only the field "u", tested by itself
  std::vector<std::string> regions;                // one per term
  std::vector<int> dirichlet_dofs;                 // values taken from the initial guess
  std::string solver = "umfpack";

  // Solves R(u) = 0 by one Newton step from u (whose Dirichlet dofs hold the boundary values).
  Eigen::VectorXd solve(Eigen::VectorXd u) const {
    DofLayout layout;
    layout.add_field("u", space.num_dofs(), dirichlet_dofs);
    SystemMatrix matrix(layout);
    std::vector<std::unique_ptr<TermAssembly>> assemblies;
    std::vector<int> handles;
    for (size_t t = 0; t < terms.size(); ++t) {
      assemblies.push_back(std::make_unique<TermAssembly>(terms[t], regions[t], std::vector<const FESpace*>{&space}));
      for (size_t k = 0; k < terms[t]->couplings().size(); ++k)
        handles.push_back(matrix.declare(0, 0, assemblies.back()->block(int(k))));
    }
    matrix.finalize();
    Eigen::VectorXd residual = Eigen::VectorXd::Zero(space.num_dofs());
    const Eigen::VectorXd* values[] = {&u};
    Eigen::VectorXd* residuals[] = {&residual};
    int h = 0;
    for (auto& a : assemblies) {
      a->assemble(values, 0.0, residuals, true);
      for (size_t k = 0; k < a->term().couplings().size(); ++k) matrix.add(handles[h++], a->block(int(k)));
    }
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(layout.size());
    layout.add_to_global(0, residual, rhs);
    auto linear = make_linear_solver(solver);
    const Eigen::VectorXd dx = linear->solve_once(matrix.matrix(), -rhs);
    layout.add_from_global(0, dx, u);
    return u;
  }
};

}  // namespace pc::testing
