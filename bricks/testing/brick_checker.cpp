#include "bricks/testing/brick_checker.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>

#include "assembly/error.hpp"
#include "assembly/mesh_generators.hpp"
#include "assembly/term_assembly.hpp"

namespace pc {
namespace {

using State = std::map<std::string, Eigen::VectorXd>;
using Residuals = std::map<std::string, Eigen::VectorXd>;                         // by test field
using Tangents = std::map<std::pair<std::string, std::string>, Eigen::MatrixXd>;  // by (test, trial)

constexpr double kTime = 0.3;  // any time: sources are checked at a time that is not special

BrickCheckSetup make_setup(std::shared_ptr<const Mesh> mesh, int order) {
  BrickCheckSetup setup;
  setup.mesh = mesh;
  const int dim = mesh->dim();
  for (const char* vector_field : {"v", "u", "a", "v_prev", "u_prev"})
    setup.spaces[vector_field] = std::make_shared<const FESpace>(mesh, order, dim);
  for (const char* scalar_field : {"phi", "phi_prev"})
    setup.spaces[scalar_field] = std::make_shared<const FESpace>(mesh, order, 1);
  return setup;
}

// The brick's terms bound to the setup's spaces, assembled together.
class BrickAssembly {
 public:
  BrickAssembly(const Brick& brick, const BrickCheckSetup& setup) {
    for (const BrickTerm& bt : brick.terms()) {
      std::vector<const FESpace*> spaces;
      for (const FieldUse& use : bt.term->fields()) {
        const auto it = setup.spaces.find(use.name);
        require(it != setup.spaces.end(), "check_brick: brick '", brick.name(), "' names field '", use.name,
                "', which the setup has no space for");
        spaces.push_back(it->second.get());
        fields_.insert(use.name);
      }
      assemblies_.push_back(std::make_unique<TermAssembly>(bt.term, bt.region, spaces));
    }
  }

  const std::set<std::string>& fields() const { return fields_; }

  void evaluate(const State& state, Residuals* residuals, Tangents* tangents) {
    for (auto& a : assemblies_) {
      const Term& term = a->term();
      std::vector<const Eigen::VectorXd*> values;
      for (const FieldUse& use : term.fields()) values.push_back(&state.at(use.name));
      std::vector<Eigen::VectorXd*> outputs;
      for (int t : term.tests()) {
        const std::string& name = term.fields()[t].name;
        if (residuals == nullptr) {
          outputs.push_back(nullptr);
          continue;
        }
        auto [it, inserted] = residuals->try_emplace(name, Eigen::VectorXd::Zero(a->space(t).num_dofs()));
        outputs.push_back(&it->second);
      }
      a->assemble(values, kTime, outputs, tangents != nullptr);
      if (tangents == nullptr) continue;
      for (int k = 0; k < int(term.couplings().size()); ++k) {
        const Coupling& c = term.couplings()[k];
        const auto key = std::make_pair(term.fields()[c.test].name, term.fields()[c.trial].name);
        const Eigen::MatrixXd block = Eigen::MatrixXd(a->block(k));
        auto [it, inserted] = tangents->try_emplace(key, Eigen::MatrixXd::Zero(block.rows(), block.cols()));
        it->second += block;
      }
    }
  }

 private:
  std::vector<std::unique_ptr<TermAssembly>> assemblies_;
  std::set<std::string> fields_;
};

State random_state(const BrickCheckSetup& setup, const std::set<std::string>& fields, std::mt19937& rng) {
  State state;
  for (const std::string& name : fields) {
    const auto range = setup.ranges.count(name) ? setup.ranges.at(name) : std::make_pair(-1.0, 1.0);
    std::uniform_real_distribution<double> uniform(range.first, range.second);
    Eigen::VectorXd x(setup.spaces.at(name)->num_dofs());
    for (double& value : x) value = uniform(rng);
    state[name] = x;
  }
  return state;
}

double max_abs(const Tangents& tangents) {
  double m = 0;
  for (const auto& [key, K] : tangents) m = std::max(m, K.cwiseAbs().maxCoeff());
  return m;
}

bool all_finite(const Residuals& r, const Tangents& t) {
  for (const auto& [name, v] : r)
    if (!v.allFinite()) return false;
  for (const auto& [key, K] : t)
    if (!K.allFinite()) return false;
  return true;
}

double max_abs(const Residuals& residuals, const std::string& test) {
  const auto it = residuals.find(test);
  return it == residuals.end() || it->second.size() == 0 ? 0.0 : it->second.cwiseAbs().maxCoeff();
}

// Each tangent column K e_j against central differences (R(x + h e_j) - R(x - h e_j)) / 2h at several
// steps h = fd_step * {0.1, 1, 10, 100} * max(1, |x_j|), keeping the best: a finite difference is off by
// its truncation error at large h and by round-off at small h, and a correct tangent matches it at the
// step between. Differences below the round-off of the step, kRoundOff eps_mach |R|_inf / h (|R| of the
// test field at x +- h e_j), are not counted: they are what finite differences cannot resolve. A wrong
// tangent (a block 1% off) differs by far more than both at every step.
constexpr double kRoundOff = 8;  // the suite's bricks show at most 3
constexpr double kStepScales[] = {0.1, 1.0, 10.0, 100.0};

void check_tangent(BrickAssembly& assembly, const BrickCheckSetup& setup, const State& state, int sample,
                   BrickCheckReport& report) {
  Tangents tangents;
  Residuals base;
  assembly.evaluate(state, &base, &tangents);
  const double scale = 1e-12 * std::max(max_abs(tangents), 1e-300);
  constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
  std::set<std::string> trials;
  for (const auto& [key, K] : tangents) trials.insert(key.second);
  for (const std::string& trial : trials) {
    const int n = static_cast<int>(state.at(trial).size());
    for (int j = 0; j < n; ++j) {
      // Best error (and its finite differences) per test field over the steps.
      std::map<std::string, double> best;
      for (const auto& [test, r] : base) best[test] = std::numeric_limits<double>::infinity();
      for (const double step_scale : kStepScales) {
        State plus = state, minus = state;
        const double x = state.at(trial)[j];
        plus[trial][j] = x + setup.fd_step * step_scale * std::max(1.0, std::abs(x));
        minus[trial][j] = x - setup.fd_step * step_scale * std::max(1.0, std::abs(x));
        const double h2 = plus[trial][j] - minus[trial][j];  // the step actually taken, twice
        Residuals rp, rm;
        assembly.evaluate(plus, &rp, nullptr);
        assembly.evaluate(minus, &rm, nullptr);
        for (const auto& [test, r] : base) {
          const Eigen::VectorXd fd = (rp.at(test) - rm.at(test)) / h2;
          const auto it = tangents.find({test, trial});
          const Eigen::VectorXd column =
              it == tangents.end() ? Eigen::VectorXd::Zero(fd.size()) : Eigen::VectorXd(it->second.col(j));
          const double round_off = kRoundOff * kEpsilon * std::max(max_abs(rp, test), max_abs(rm, test)) / (0.5 * h2);
          const double denominator = std::max({fd.cwiseAbs().maxCoeff(), column.cwiseAbs().maxCoeff(), scale});
          double error = std::max(0.0, (column - fd).cwiseAbs().maxCoeff() - round_off) / denominator;
          if (!column.allFinite() || !fd.allFinite()) error = std::numeric_limits<double>::infinity();
          best[test] = std::min(best[test], error);
        }
      }
      for (const auto& [test, error] : best) {
        ++report.tangent_checks;
        report.max_tangent_error = std::max(report.max_tangent_error, error);
        if (!(error <= setup.fd_tolerance))
          report.failures.push_back(message("tangent d R_", test, " / d ", trial, " column ", j, " (sample ", sample,
                                            ") differs from finite differences by ", error, " at best over steps",
                                            tangents.count({test, trial}) ? "" : " (no coupling declared)"));
      }
    }
  }
}

void check_linear(BrickAssembly& assembly, const BrickCheckSetup& setup, const State& state, BrickCheckReport& report) {
  State zero = state;
  for (auto& [name, x] : zero) x.setZero();
  Residuals r0, rx;
  Tangents k0, kx;
  assembly.evaluate(zero, &r0, &k0);
  assembly.evaluate(state, &rx, &kx);
  const double scale = std::max(max_abs(kx), 1e-300);
  for (const auto& [key, K] : kx) {
    const double change = (K - k0.at(key)).cwiseAbs().maxCoeff() / scale;
    report.max_linear_error = std::max(report.max_linear_error, change);
    if (change > setup.linear_tolerance)
      report.failures.push_back(message("claims linear, but tangent d R_", key.first, " / d ", key.second,
                                        " changes with the state by ", change));
  }
  for (const auto& [test, r] : rx) {
    Eigen::VectorXd predicted = r0.at(test);
    for (const auto& [key, K] : kx)
      if (key.first == test) predicted += K * state.at(key.second);
    const double size = std::max({r.cwiseAbs().maxCoeff(), predicted.cwiseAbs().maxCoeff(), 1e-300});
    const double error = (r - predicted).cwiseAbs().maxCoeff() / size;
    report.max_linear_error = std::max(report.max_linear_error, error);
    if (error > setup.linear_tolerance)
      report.failures.push_back(message("claims linear, but R_", test, "(x) differs from K x + R(0) by ", error));
  }
}

void check_symmetric(BrickAssembly& assembly, const BrickCheckSetup& setup, const State& state,
                     BrickCheckReport& report) {
  Tangents tangents;
  assembly.evaluate(state, nullptr, &tangents);
  // In a model, a block with respect to an affine field lands in its base unknown's columns.
  auto base = [&](const std::string& name) {
    const auto it = setup.affine_base.find(name);
    return it == setup.affine_base.end() ? name : it->second;
  };
  Tangents folded;
  for (const auto& [key, K] : tangents) {
    auto [it, inserted] = folded.try_emplace({key.first, base(key.second)}, Eigen::MatrixXd::Zero(K.rows(), K.cols()));
    it->second += K;
  }
  const double scale = std::max(max_abs(folded), 1e-300);
  for (const auto& [key, K] : folded) {
    const auto transposed = folded.find({key.second, key.first});
    const Eigen::MatrixXd other =
        transposed == folded.end() ? Eigen::MatrixXd::Zero(K.cols(), K.rows()) : Eigen::MatrixXd(transposed->second);
    const double error = (K - other.transpose()).cwiseAbs().maxCoeff() / scale;
    report.max_symmetry_error = std::max(report.max_symmetry_error, error);
    if (error > setup.symmetry_tolerance)
      report.failures.push_back(message("claims symmetric, but block (", key.first, ", ", key.second,
                                        ") differs from the transpose of (", key.second, ", ", key.first, ") by ",
                                        error));
  }
}

}  // namespace

ConstantTable& ConstantTable::set(const std::string& name, Eigen::MatrixXd value) {
  values_[name] = std::move(value);
  return *this;
}

ConstantTable& ConstantTable::set(const std::string& name, double value) {
  return set(name, Eigen::MatrixXd::Constant(1, 1, value));
}

ConstantTable& ConstantTable::set(const ParameterValues& values) {
  for (const auto& [name, value] : values) set(name, value);
  return *this;
}

const Eigen::MatrixXd& ConstantTable::constant(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) {
    std::string known;
    for (const auto& [n, v] : values_) known += (known.empty() ? "" : ", ") + n;
    fail("unknown datum '", name, "' (known: ", known.empty() ? "none" : known, ")");
  }
  return it->second;
}

BrickCheckSetup BrickCheckSetup::square(Shape shape, int order) {
  return make_setup(std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 2, 2, shape)), order);
}

BrickCheckSetup BrickCheckSetup::cube(Shape shape, int order) {
  return make_setup(std::make_shared<const Mesh>(box_mesh({0, 0, 0}, {1, 1, 1}, 1, 1, 1, shape)), order);
}

std::ostream& operator<<(std::ostream& out, const BrickCheckReport& report) {
  out << "brick '" << report.brick << "': " << report.tangent_checks << " tangent columns checked, max errors: tangent "
      << report.max_tangent_error << ", linear " << report.max_linear_error << ", symmetry "
      << report.max_symmetry_error;
  for (const std::string& f : report.failures) out << "\n  - " << f;
  return out;
}

BrickCheckReport check_brick(Brick& brick, const DataView& data, const BrickCheckSetup& setup) {
  BrickCheckReport report;
  report.brick = brick.name();
  brick.update(data);
  BrickAssembly assembly(brick, setup);
  std::mt19937 rng(setup.seed);
  for (int sample = 0; sample < setup.samples; ++sample) {
    const State state = random_state(setup, assembly.fields(), rng);
    check_tangent(assembly, setup, state, sample, report);
    if (brick.linear()) check_linear(assembly, setup, state, report);
    if (brick.symmetric()) check_symmetric(assembly, setup, state, report);
  }
  const State state = random_state(setup, assembly.fields(), rng);
  for (double s : setup.extreme_scales) {
    State scaled = state;
    for (auto& [name, x] : scaled) x *= s;
    Residuals r;
    Tangents t;
    assembly.evaluate(scaled, &r, &t);
    if (!all_finite(r, t))
      report.failures.push_back(message("non-finite residual or tangent at a state scaled by ", s));
  }
  return report;
}

}  // namespace pc
