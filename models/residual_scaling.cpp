#include "models/residual_scaling.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "assembly/processes.hpp"
#include "assembly/threads.hpp"

namespace pc {
namespace {

// Products with fewer entries stay on one thread (starting threads would cost more than they save).
constexpr long kMinProductEntriesForThreads = 20000;

// One value per unknown, in the layout's order (its blocks').
std::vector<double> in_layout_order(const DofLayout& l, const std::map<std::string, double>& per_unknown) {
  std::vector<double> values;
  for (int f = 0; f < l.num_fields(); ++f) values.push_back(per_unknown.at(l.field_name(f)));
  return values;
}

}  // namespace

void ResidualScaling::reset(const std::vector<std::string>& unknowns) {
  for (const std::string& u : unknowns) {
    residual_[u] = 0;
    round_off_[u] = 0;
  }
}

void ResidualScaling::record(const std::string& u, double net, double gross) {
  residual_[u] = std::max(residual_[u], net);
  round_off_[u] = std::max({round_off_[u], net, gross});
}

void ResidualScaling::measure(const std::string& u, const Eigen::VectorXd& r, std::span<const int> global,
                              double gross) {
  double sum = 0;
  for (int d = 0; d < int(global.size()); ++d)
    if (global[d] >= 0) {
      const double value = r[d];
      sum += value * value;
    }
  record(u, std::sqrt(sum), gross);
}

void ResidualScaling::add_measured(const std::string& u, const Eigen::VectorXd& r, std::span<const int> global,
                                   Eigen::VectorXd& out) {
  double sum = 0;
  for (int d = 0; d < int(global.size()); ++d) {
    if (global[d] >= 0) sum += r[d] * r[d];
    out[d] += r[d];
  }
  record(u, std::sqrt(sum), 0);
}

void ResidualScaling::add_measured_product(const std::string& u, const CsrView& K, const Eigen::VectorXd& x,
                                           std::span<const int> global, Eigen::VectorXd& out) {
  const int* start = K.outerIndexPtr();
  const int* column = K.innerIndexPtr();
  const double* value = K.valuePtr();
  const int rows = int(K.rows());
  // Rows in parallel (each is its own sum), their norms then summed in row order: bitwise the same on
  // any number of threads.
  product_rows_.resize(rows);
  gross_rows_.resize(rows);
  const int threads = K.nonZeros() >= kMinProductEntriesForThreads ? assembly_threads() : 1;
  const bool shares = processes::distributed();
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1)
#endif
  for (int r = 0; r < rows; ++r) {
    double row = 0, row_gross = 0;
    for (int k = start[r]; k < start[r + 1]; ++k) {
      const double term = value[k] * x[column[k]];
      row += term;
      row_gross += std::abs(term);
    }
    if (!shares) out[r] += row;
    product_rows_[r] = row;
    gross_rows_[r] = row_gross;
  }
  // Distributed, K is this process's share: the rows are summed over the processes (a row's gross size
  // then sums each share's, an upper bound of the undivided |K| |x|), then added.
  if (shares) {
    processes::sum(product_rows_);
    processes::sum(gross_rows_);
    for (int r = 0; r < rows; ++r) out[r] += product_rows_[r];
  }
  double net = 0, gross = 0;
  for (int r = 0; r < rows; ++r)
    if (global[r] >= 0) {
      net += product_rows_[r] * product_rows_[r];
      gross += gross_rows_[r] * gross_rows_[r];
    }
  record(u, std::sqrt(net), std::sqrt(gross));
}

void ResidualScaling::at_least_that_of(const std::string& own, const std::string& like) {
  residual_[own] = std::max(residual_[own], residual_[like]);
}

std::vector<double> ResidualScaling::residual_scales(const DofLayout& layout) const {
  return in_layout_order(layout, residual_);
}

std::vector<double> ResidualScaling::round_off_scales(const DofLayout& layout) const {
  return in_layout_order(layout, round_off_);
}

void ResidualScaling::restore(std::map<std::string, double> residual, std::map<std::string, double> round_off) {
  residual_ = std::move(residual);
  round_off_ = std::move(round_off);
}

}  // namespace pc
