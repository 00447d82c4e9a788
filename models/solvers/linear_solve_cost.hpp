#pragma once
// The work of a linear strategy's solves, by phase: each strategy returns its own, and Newton adds it into
// its report, so that no strategy writes into Newton's bookkeeping.
namespace pc {

struct LinearSolveCost {
  double analyze_seconds = 0, factorize_seconds = 0, solve_seconds = 0;
  double condensation_seconds = 0;  // dense interface systems of the condensed solve
  int factorizations = 0;           // sparse numeric factorisations
  int dense_factorizations = 0;     // LU factorisations of the condensed solve's dense interface systems

  LinearSolveCost& operator+=(const LinearSolveCost& other) {
    analyze_seconds += other.analyze_seconds;
    factorize_seconds += other.factorize_seconds;
    solve_seconds += other.solve_seconds;
    condensation_seconds += other.condensation_seconds;
    factorizations += other.factorizations;
    dense_factorizations += other.dense_factorizations;
    return *this;
  }
};

}  // namespace pc
