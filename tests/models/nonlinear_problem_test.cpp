// Newton on hand-written NonlinearProblems that are not a Model (models/solvers/nonlinear_problem.hpp): the
// solver sees only the narrow interface. A 2 x 2 system with a known root shows quadratic convergence, block
// by block; a chain of linear springs held by cubic springs exercises the condensed solve (their nodes are
// the nonlinear dofs), by both methods, and its fall-back when the linear part is singular (a chain held by
// the cubic springs only).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "models/solvers/newton.hpp"
#include "models/solvers/nonlinear_problem.hpp"

namespace pc {
namespace {

CsrMatrix from_triplets(int n, const std::vector<Eigen::Triplet<double>>& entries) {
  CsrMatrix m(n, n);
  m.setFromTriplets(entries.begin(), entries.end());
  m.makeCompressed();
  return m;
}

// x^2 + y^2 = 4 and x y = 1 (a circle and a hyperbola), one block per unknown; the root near (2, 1) is
// x = (sqrt 6 + sqrt 2) / 2, y = (sqrt 6 - sqrt 2) / 2. Every iterate is recorded when it is assembled.
class CircleHyperbola : public NonlinearProblem {
 public:
  CircleHyperbola() : x_(Eigen::Vector2d(2, 1)) {
    jacobian_ = from_triplets(2, {{0, 0, 1}, {0, 1, 1}, {1, 0, 1}, {1, 1, 1}});
    linear_ = jacobian_;
    linear_.coeffs().setZero();  // every term depends on x
  }
  void assemble(bool tangent) override {
    iterates.push_back(x_);
    const double x = x_[0], y = x_[1];
    residual_ = Eigen::Vector2d(x * x + y * y - 4, x * y - 1);
    scales_ = {std::max({x * x, y * y, 4.0}), std::max(std::abs(x * y), 1.0)};
    if (tangent) jacobian_.coeffs() << 2 * x, 2 * y, y, x;  // row-major: (0,0) (0,1) (1,0) (1,1)
  }
  const Eigen::VectorXd& residual() const override { return residual_; }
  const CsrMatrix& jacobian() const override { return jacobian_; }
  const CsrMatrix& linear_jacobian() override { return linear_; }
  std::uint64_t linear_jacobian_version() override { return 1; }
  const std::vector<int>& nonlinear_dofs() override { return nonlinear_; }
  std::vector<ProblemBlock> blocks() const override { return {{"x", 0, 1}, {"y", 1, 1}}; }
  std::vector<double> residual_scales() const override { return scales_; }
  Eigen::VectorXd free_values() const override { return x_; }
  void set_free_values(const Eigen::VectorXd& x) override { x_ = x; }
  void add_to_free_values(const Eigen::VectorXd& step) override { x_ += step; }
  std::map<std::string, double> diagnostics() const override { return {{"iterates", double(iterates.size())}}; }

  static Eigen::Vector2d root() {
    return Eigen::Vector2d(std::sqrt(6.0) + std::sqrt(2.0), std::sqrt(6.0) - std::sqrt(2.0)) / 2;
  }
  std::vector<Eigen::VectorXd> iterates;

 private:
  Eigen::VectorXd x_, residual_;
  std::vector<double> scales_;
  CsrMatrix jacobian_, linear_;
  std::vector<int> nonlinear_ = {0, 1};
};

TEST(NonlinearProblem, NewtonConvergesQuadraticallyOnAHandWrittenSystem) {
  CircleHyperbola problem;
  NewtonOptions options;
  options.line_search = false;  // pure Newton: one assembly per iteration
  const NewtonReport report = NewtonSolver(options).solve(problem);
  ASSERT_TRUE(report.converged()) << report.message;
  EXPECT_EQ(report.blocks, (std::vector<std::string>{"x", "y"}));
  EXPECT_FALSE(report.condensed) << "every dof is nonlinear: the condensed solve does not apply";
  EXPECT_EQ(report.diagnostics.at("iterates"), double(problem.iterates.size()));
  EXPECT_LT((problem.free_values() - CircleHyperbola::root()).norm(), 1e-11);
  // e_{k+1} <= C e_k^2 while e_k is above round-off (C = |J^-1| |R''| / 2 is about 0.5 here).
  int measured = 0;
  for (size_t k = 0; k + 1 < problem.iterates.size(); ++k) {
    const double e = (problem.iterates[k] - CircleHyperbola::root()).norm();
    const double next = (problem.iterates[k + 1] - CircleHyperbola::root()).norm();
    if (e < 1e-6) break;
    EXPECT_LT(next / (e * e), 0.6) << "iteration " << k;
    ++measured;
  }
  EXPECT_GE(measured, 3);
  EXPECT_LE(report.iterations, 6);
}

// n unit springs in a row, node 0 pulled by a unit force and the nodes `held` tied to the ground by springs
// of force x + cubic x^3 (the nonlinear dofs). Anchored: node 0 is also tied to the ground by a unit spring,
// so the linear part A is regular; free: A is the singular Laplacian of a chain that only the cubic springs
// hold. With cubic = 0 the ground springs are linear, yet outside A: a tangent D that never changes.
class SpringChain : public NonlinearProblem {
 public:
  // unheld: further nonlinear dofs that no spring holds (D is zero there: contact nodes out of contact).
  SpringChain(int n, bool anchored, std::vector<int> held, double cubic = 1, std::vector<int> unheld = {})
      : n_(n),
        cubic_(cubic),
        x_(Eigen::VectorXd::Zero(n)),
        f_(Eigen::VectorXd::Zero(n)),
        held_(held),
        nonlinear_(std::move(held)) {
    nonlinear_.insert(nonlinear_.end(), unheld.begin(), unheld.end());
    std::sort(nonlinear_.begin(), nonlinear_.end());
    std::vector<Eigen::Triplet<double>> entries;
    for (int i = 0; i + 1 < n; ++i)
      for (auto [r, c, v] : {std::tuple{i, i, 1.0}, {i + 1, i + 1, 1.0}, {i, i + 1, -1.0}, {i + 1, i, -1.0}})
        entries.emplace_back(r, c, v);
    if (anchored) entries.emplace_back(0, 0, 1.0);
    linear_ = from_triplets(n, entries);
    jacobian_ = linear_;
    f_[0] = 1;
  }
  void assemble(bool tangent) override {
    ++whole_assemblies;
    const Eigen::VectorXd internal = linear_ * x_;
    residual_ = internal - f_;
    scales_ = {std::max(internal.norm(), f_.norm())};
    if (tangent) jacobian_ = linear_;
    for (int i : held_) {
      const double x = x_[i];
      residual_[i] += x + cubic_ * x * x * x;
      scales_[0] = std::max(scales_[0], std::abs(x + cubic_ * x * x * x));
      if (tangent) jacobian_.coeffRef(i, i) += 1 + 3 * cubic_ * x * x;
    }
  }
  const Eigen::VectorXd& residual() const override { return residual_; }
  const CsrMatrix& jacobian() const override { return jacobian_; }
  const CsrMatrix& linear_jacobian() override { return linear_; }
  std::uint64_t linear_jacobian_version() override { return 1; }
  const std::vector<int>& nonlinear_dofs() override { return nonlinear_; }
  std::vector<ProblemBlock> blocks() const override { return {{"x", 0, n_}}; }
  std::vector<double> residual_scales() const override { return scales_; }
  Eigen::VectorXd free_values() const override { return x_; }
  void set_free_values(const Eigen::VectorXd& x) override { x_ = x; }
  void add_to_free_values(const Eigen::VectorXd& step) override { x_ += step; }
  std::map<std::string, double> diagnostics() const override { return {}; }
  // The ground springs' forces on the nonlinear rows, and their tangent: what Newton on the contact dofs
  // reads (unless gives_nonlinear_rows is false).
  bool assemble_nonlinear_rows(Eigen::VectorXd& rows) override {
    if (!gives_nonlinear_rows) return false;
    rows = Eigen::VectorXd::Zero(Eigen::Index(nonlinear_.size()));
    jacobian_ = linear_;
    for (size_t k = 0; k < nonlinear_.size(); ++k) {
      const int i = nonlinear_[k];
      if (std::find(held_.begin(), held_.end(), i) == held_.end()) continue;
      const double x = x_[i];
      rows[Eigen::Index(k)] = x + cubic_ * x * x * x;
      jacobian_.coeffRef(i, i) += 1 + 3 * cubic_ * x * x;
    }
    return true;
  }

  bool gives_nonlinear_rows = true;
  int whole_assemblies = 0;  // assemble() calls: residuals of the whole system

 private:
  int n_;
  double cubic_;
  Eigen::VectorXd x_, f_, residual_;
  std::vector<double> scales_;
  std::vector<int> held_, nonlinear_;
  CsrMatrix linear_, jacobian_;
};

Eigen::VectorXd solve_in_full(int n, bool anchored, const std::vector<int>& held) {
  SpringChain problem(n, anchored, held);
  NewtonOptions options;
  options.condensed_max_fraction = 0;
  const NewtonReport report = NewtonSolver(options).solve(problem);
  EXPECT_TRUE(report.converged()) << report.message;
  EXPECT_FALSE(report.condensed);
  return problem.free_values();
}

TEST(NonlinearProblem, CondensedSolveFactorisesTheLinearPartOnceAndMatchesTheFullSolve) {
  const int n = 40;
  const Eigen::VectorXd full = solve_in_full(n, true, {n - 1});
  for (const char* method : {"schur", "columns"}) {
    SpringChain problem(n, true, {n - 1});
    NewtonOptions options;
    options.condensation = method;
    NewtonSolver newton(options);
    const NewtonReport report = newton.solve(problem);
    ASSERT_TRUE(report.converged()) << method << ": " << report.message;
    EXPECT_TRUE(report.condensed) << method;
    EXPECT_GT(report.iterations, 1) << method << ": the cubic spring needs several iterations";
    EXPECT_EQ(report.factorizations, 1) << method << ": A is factorised once, whatever the iterations";
    EXPECT_LT((problem.free_values() - full).norm(), 1e-12 * full.norm()) << method;
    // A second solve of the same problem keeps the factorisation.
    problem.set_free_values(Eigen::VectorXd::Zero(n));
    const NewtonReport again = newton.solve(problem);
    EXPECT_TRUE(again.converged() && again.condensed) << method;
    EXPECT_EQ(again.factorizations, 0) << method;
  }
}

// The Schur path's dense Woodbury system (1 + D_II S_c^-1[I, I]) is factorised again only when the active
// set or D_II changed: once per iteration for the cubic springs, once in all for linear ones, whose D is
// the same at every iterate and in the next solve.
TEST(NonlinearProblem, SchurCondensationRefactorisesItsDenseSystemOnlyWhenTheContactTangentChanges) {
  const int n = 40;
  const std::vector<int> held = {10, 25, n - 1};
  SpringChain cubic(n, true, held);
  NewtonOptions options;
  options.condensation = "schur";
  const NewtonReport changing = NewtonSolver(options).solve(cubic);
  ASSERT_TRUE(changing.converged()) << changing.message;
  EXPECT_GT(changing.iterations, 2);
  EXPECT_EQ(changing.dense_factorizations, changing.iterations);

  SpringChain linear(n, true, held, 0.0);
  NewtonSolver newton(options);
  const NewtonReport first = newton.solve(linear);
  ASSERT_TRUE(first.converged()) << first.message;
  EXPECT_EQ(first.dense_factorizations, 1);
  linear.set_free_values(Eigen::VectorXd::Constant(n, 0.5));
  const NewtonReport again = newton.solve(linear);
  ASSERT_TRUE(again.converged()) << again.message;
  EXPECT_GE(again.iterations, 1);
  EXPECT_EQ(again.dense_factorizations, 0) << "the same D: the kept factorisation serves";
  // And the kept factorisation gives the right answer: the residual of the linear chain vanishes.
  linear.assemble(false);
  EXPECT_LT(linear.residual().norm(), 1e-12);
}

// The Schur path's Woodbury system on the active dofs (those a spring holds; D is zero on the others, as on
// contact nodes out of contact) reaches the full solve's answer with few, most or all of the nonlinear dofs
// active, and is refactorised only when D changes (every iteration, for cubic springs).
TEST(NonlinearProblem, TheSchurPathsWoodburySystemOnTheActiveDofsReachesTheFullSolution) {
  const int n = 60;
  const std::vector<int> candidates = {5, 10, 15, 20, 25, 30, 35, 40, 45, 50, 55, 59};
  for (const int held_count : {2, 11, 12}) {  // 1/6, 11/12 and all of them active
    const std::vector<int> held(candidates.end() - held_count, candidates.end());
    const std::vector<int> unheld(candidates.begin(), candidates.end() - held_count);
    SpringChain full(n, true, held, 1.0, unheld);
    NewtonOptions in_full;
    in_full.condensed_max_fraction = 0;
    ASSERT_TRUE(NewtonSolver(in_full).solve(full).converged());
    SpringChain condensed(n, true, held, 1.0, unheld);
    NewtonOptions options;
    options.condensation = "schur";
    const NewtonReport report = NewtonSolver(options).solve(condensed);
    ASSERT_TRUE(report.converged()) << held_count << ": " << report.message;
    EXPECT_TRUE(report.condensed) << held_count;
    EXPECT_EQ(report.factorizations, 1) << held_count;
    EXPECT_EQ(report.dense_factorizations, report.iterations) << held_count;
    EXPECT_LT((condensed.free_values() - full.free_values()).norm(), 1e-12 * full.free_values().norm()) << held_count;
  }
}

// Newton on the contact dofs (NewtonOptions::contact_newton, reduced_contact_system.hpp) takes the whole
// system's iterates: the same number of iterations, the same residual norms block by block (the interior's
// residual is zero once the first step lands on it), the same answer. It assembles the whole residual
// twice, at the start and to verify, where the whole system's iterations assemble it once per iteration;
// a problem that cannot assemble its nonlinear rows alone is iterated on the whole system.
TEST(NonlinearProblem, NewtonOnTheContactDofsTakesTheWholeSystemsIteratesWithTwoWholeResiduals) {
  const int n = 60;
  const std::vector<int> held = {10, 25, 40, 59}, unheld = {5, 33};
  NewtonOptions whole_options;
  whole_options.condensation = "schur";
  whole_options.contact_newton = false;
  SpringChain whole(n, true, held, 1.0, unheld);
  const NewtonReport on_whole = NewtonSolver(whole_options).solve(whole);
  ASSERT_TRUE(on_whole.converged()) << on_whole.message;
  EXPECT_EQ(on_whole.contact_iterations, 0);
  EXPECT_EQ(whole.whole_assemblies, on_whole.iterations + 1);

  NewtonOptions options = whole_options;
  options.contact_newton = true;
  SpringChain reduced(n, true, held, 1.0, unheld);
  const NewtonReport on_contact = NewtonSolver(options).solve(reduced);
  ASSERT_TRUE(on_contact.converged()) << on_contact.message;
  EXPECT_GE(on_contact.iterations, 3) << "the cubic springs need several iterations";
  EXPECT_EQ(on_contact.iterations, on_whole.iterations);
  EXPECT_EQ(on_contact.contact_iterations, on_contact.iterations);
  EXPECT_EQ(reduced.whole_assemblies, 2) << "the residual of the whole system at the start and at the end";
  EXPECT_EQ(on_contact.factorizations, 1);
  EXPECT_EQ(on_contact.dense_factorizations, on_contact.iterations);
  EXPECT_LT((reduced.free_values() - whole.free_values()).norm(), 1e-12 * whole.free_values().norm());
  // The iterates' residuals, until they reach round-off: the same to a few digits past the largest.
  ASSERT_EQ(on_contact.history.size(), on_whole.history.size());
  const double first = on_whole.history[0].residual_norms[0];
  for (size_t k = 0; k < on_whole.history.size(); ++k) {
    const double expected = on_whole.history[k].residual_norms[0];
    EXPECT_NEAR(on_contact.history[k].residual_norms[0], expected, 1e-9 * first + 1e-6 * expected) << "iteration " << k;
  }
  // The verdict is the whole residual's: the last entry is it, and it meets the tolerance.
  reduced.assemble(false);
  EXPECT_EQ(on_contact.history.back().residual_norms[0], reduced.residual().norm());

  SpringChain without_rows(n, true, held, 1.0, unheld);
  without_rows.gives_nonlinear_rows = false;
  const NewtonReport fallback = NewtonSolver(options).solve(without_rows);
  ASSERT_TRUE(fallback.converged()) << fallback.message;
  EXPECT_EQ(fallback.contact_iterations, 0);
  EXPECT_EQ(without_rows.whole_assemblies, fallback.iterations + 1);
  EXPECT_LT((without_rows.free_values() - whole.free_values()).norm(), 1e-12 * whole.free_values().norm());
}

// Past condensed_max_dofs nonlinear dofs the dense work (m^3) would exceed a full factorisation's: the
// problem is solved in full, to the same answer.
TEST(NonlinearProblem, TooManyNonlinearDofsAreSolvedInFull) {
  const int n = 40;
  const std::vector<int> held = {5, 10, 15, 20, 25, 30, 35, 39};
  const Eigen::VectorXd full = solve_in_full(n, true, held);
  for (const int cap : {8, 7}) {
    SpringChain problem(n, true, held);
    NewtonOptions options;
    options.condensation = "schur";
    options.condensed_max_dofs = cap;
    const NewtonReport report = NewtonSolver(options).solve(problem);
    ASSERT_TRUE(report.converged()) << report.message;
    EXPECT_EQ(report.condensed, cap >= int(held.size())) << cap;
    EXPECT_LT((problem.free_values() - full).norm(), 1e-12 * full.norm()) << cap;
  }
}

// GMRES preconditioned by a kept factorisation of an earlier J: the Newton iterates are those of exact
// steps (to the GMRES tolerance), with fewer factorisations than iterations: J changes only on the cubic
// springs' dofs from one iteration to the next.
TEST(NonlinearProblem, KrylovStepsReachTheFullSolutionWithFewerFactorisations) {
  const int n = 200;
  const std::vector<int> held = {20, 60, 100, 140, 180, 199};
  const Eigen::VectorXd full = solve_in_full(n, true, held);
  SpringChain problem(n, true, held);
  NewtonOptions options;
  options.condensation = "krylov";
  NewtonSolver newton(options);
  const NewtonReport report = newton.solve(problem);
  ASSERT_TRUE(report.converged()) << report.message;
  EXPECT_TRUE(report.condensed);
  EXPECT_EQ(report.strategy, LinearStrategy::Krylov);
  EXPECT_GT(report.iterations, 2);
  EXPECT_LT(report.factorizations, report.iterations) << "the factorisation of J_ref is kept between iterations";
  EXPECT_GT(report.krylov_iterations, 0);
  // J_ref^-1 J is the identity plus a rank of at most 6 (the held dofs): GMRES needs at most 7 per step.
  EXPECT_LE(report.krylov_iterations, 7 * report.iterations);
  EXPECT_LT((problem.free_values() - full).norm(), 1e-10 * full.norm());
}

// auto weighs the strategies by the cost model: six nonlinear dofs of 200 are condensed by Schur, and the
// choice is explained; a problem whose dofs are all nonlinear is solved in full.
TEST(NonlinearProblem, AutoChoosesByTheCostModelAndSaysWhy) {
  const int n = 200;
  SpringChain chain(n, true, {20, 60, 100, 140, 180, 199});
  NewtonSolver newton;  // condensation = "auto"
  const NewtonReport report = newton.solve(chain);
  ASSERT_TRUE(report.converged()) << report.message;
  EXPECT_EQ(report.strategy, LinearStrategy::Schur);
  EXPECT_NE(newton.strategy_explanation().find("6 contact dofs of 200"), std::string::npos)
      << newton.strategy_explanation();
  EXPECT_NE(newton.strategy_explanation().find(": schur"), std::string::npos) << newton.strategy_explanation();
  // Past solver.condensed_max_dofs the dense method is not taken, and the explanation says so.
  SpringChain capped(n, true, {20, 60, 100, 140, 180, 199});
  NewtonOptions options;
  options.condensed_max_dofs = 5;
  NewtonSolver capped_newton(options);
  const NewtonReport krylov = capped_newton.solve(capped);
  ASSERT_TRUE(krylov.converged()) << krylov.message;
  EXPECT_EQ(krylov.strategy, LinearStrategy::Krylov);
  EXPECT_NE(capped_newton.strategy_explanation().find("exceed solver.condensed_max_dofs = 5: krylov"),
            std::string::npos)
      << capped_newton.strategy_explanation();
  CircleHyperbola everywhere;
  const NewtonReport all = NewtonSolver().solve(everywhere);
  ASSERT_TRUE(all.converged());
  EXPECT_EQ(all.strategy, LinearStrategy::Full);
}

TEST(NonlinearProblem, ASingularLinearPartIsSchurCondensedOrSolvedInFullFromThenOn) {
  const int n = 40;
  {
    // Schur needs only the interior regular: held at both ends, the nodes between are held by the springs
    // to the ends; the Schur complement of the ends is singular, so S_c + D is factorised per iteration.
    const std::vector<int> ends = {0, n - 1};
    const Eigen::VectorXd full = solve_in_full(n, false, ends);
    SpringChain problem(n, false, ends);
    NewtonOptions options;
    options.condensation = "schur";
    const NewtonReport report = NewtonSolver(options).solve(problem);
    ASSERT_TRUE(report.converged()) << report.message;
    EXPECT_TRUE(report.condensed);
    EXPECT_LT((problem.free_values() - full).norm(), 1e-12 * full.norm());
  }
  {
    // Held by one cubic spring: the Schur complement of that node is 1 x 1 and zero up to round-off. It
    // must count as singular (S_c + D factorised), not be inverted into 1e16: the answer is the full one.
    const Eigen::VectorXd full = solve_in_full(n, false, {n - 1});
    SpringChain problem(n, false, {n - 1});
    NewtonOptions options;
    options.condensation = "schur";
    const NewtonReport report = NewtonSolver(options).solve(problem);
    ASSERT_TRUE(report.converged()) << report.message;
    EXPECT_TRUE(report.condensed);
    problem.assemble(false);
    EXPECT_LT(problem.residual().norm(), 1e-10) << "converged, so the residual must be small";
    EXPECT_LT((problem.free_values() - full).norm(), 1e-10 * full.norm());
  }
  // Columns needs A regular: its factorisation (or its solve) fails, and the problem is solved in full.
  const Eigen::VectorXd full = solve_in_full(n, false, {n - 1});
  SpringChain problem(n, false, {n - 1});
  NewtonOptions options;
  options.condensation = "columns";
  NewtonSolver newton(options);
  const NewtonReport report = newton.solve(problem);
  ASSERT_TRUE(report.converged()) << report.message;
  EXPECT_FALSE(report.condensed);
  EXPECT_LT((problem.free_values() - full).norm(), 1e-12 * full.norm());
  // From then on, without trying to condense again: one factorisation of J per iteration.
  problem.set_free_values(Eigen::VectorXd::Zero(n));
  const NewtonReport again = newton.solve(problem);
  ASSERT_TRUE(again.converged()) << again.message;
  EXPECT_FALSE(again.condensed);
  EXPECT_EQ(again.factorizations, again.iterations);
}

// R(x) = x - 1 plus a round-off of 5e-12 (alternating, whatever x is), the net size of its terms that
// round-off too, and their gross size 1e5: the round-off floor (kRoundOffFloorFactor) is
// 8 eps 1e5 = 1.8e-10. Like a model with every side clamped, whose forces cancel on every free node.
class RoundOffLine : public NonlinearProblem {
 public:
  explicit RoundOffLine(double x0) : x_(Eigen::VectorXd::Constant(1, x0)) {}
  void assemble(bool) override {
    ++assemblies_;
    residual_ = Eigen::VectorXd::Constant(1, x_[0] - 1 + (assemblies_ % 2 ? 5e-12 : -3.5e-12));
  }
  const Eigen::VectorXd& residual() const override { return residual_; }
  const CsrMatrix& jacobian() const override { return jacobian_; }
  const CsrMatrix& linear_jacobian() override { return jacobian_; }
  std::uint64_t linear_jacobian_version() override { return 1; }
  const std::vector<int>& nonlinear_dofs() override { return nonlinear_; }
  std::vector<ProblemBlock> blocks() const override { return {{"x", 0, 1}}; }
  std::vector<double> residual_scales() const override { return {std::max(std::abs(residual_[0]), 5e-12)}; }
  std::vector<double> round_off_scales() const override { return {gross_}; }
  Eigen::VectorXd free_values() const override { return x_; }
  void set_free_values(const Eigen::VectorXd& x) override { x_ = x; }
  void add_to_free_values(const Eigen::VectorXd& step) override { x_ += step; }
  std::map<std::string, double> diagnostics() const override { return {}; }

  double gross_ = 1e5;

 private:
  int assemblies_ = 0;
  Eigen::VectorXd x_, residual_;
  CsrMatrix jacobian_ = from_triplets(1, {{0, 0, 1}});
  std::vector<int> nonlinear_ = {0};
};

// At the solution the residual and its reference are round-off: the relative test alone never passes
// (25 iterations), the floor does at once.
TEST(NonlinearProblem, AResidualAtItsRoundOffFloorHasConverged) {
  RoundOffLine at_floor(1.0);
  const NewtonReport report = NewtonSolver().solve(at_floor);
  ASSERT_TRUE(report.converged()) << report.message;
  EXPECT_EQ(report.iterations, 0);
  EXPECT_NE(report.message.find("at the round-off floor of block 'x'"), std::string::npos) << report.message;

  RoundOffLine without_floor(1.0);
  without_floor.gross_ = 0;  // the floor is zero: only the relative test
  EXPECT_EQ(NewtonSolver().solve(without_floor).outcome, NewtonOutcome::MaxIterations);
}

// A tolerance below min_relative_tolerance() (from x = 2, reference 1: 1e-16 asks for a residual below
// 1e-16, the floor is 1.8e-10) ends the solve as RoundOffFloor after two iterates at the floor, naming the
// block, the floor and the tolerance; at min_relative_tolerance() the floor counts.
TEST(NonlinearProblem, AToleranceBelowTheRoundOffFloorStopsTheSolve) {
  NewtonOptions options;
  options.absolute_tolerance = 0;
  options.relative_tolerance = 1e-16;
  RoundOffLine below(2.0);
  const NewtonReport report = NewtonSolver(options).solve(below);
  EXPECT_EQ(report.outcome, NewtonOutcome::RoundOffFloor) << report.message;
  EXPECT_EQ(report.iterations, 2);
  for (const std::string part : {"block 'x'", "stagnates at its round-off floor 1.776356839e-10",
                                 "above the tolerance 1e-16 (relative_tolerance 1e-16 times 1)"})
    EXPECT_NE(report.message.find(part), std::string::npos) << report.message;
  EXPECT_EQ(to_string(report.outcome), "round_off_floor");

  options.relative_tolerance = min_relative_tolerance();
  RoundOffLine at_limit(2.0);
  const NewtonReport converged = NewtonSolver(options).solve(at_limit);
  ASSERT_TRUE(converged.converged()) << converged.message;
  EXPECT_EQ(converged.iterations, 1);
}

}  // namespace
}  // namespace pc
