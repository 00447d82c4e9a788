#include "assembly/symmetrizing_scale.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "assembly/error.hpp"

namespace pc {
namespace {

// An entry pair is strong when one of the two is at least this share of its row's largest: the scale is
// carried from row to row through strong pairs only. An entry that is a sum with cancellation (exact to
// the round-off of its row only) is small in both rows; a coupling of two fields of different units may be
// small in one row only (the piezoelectric C is 1e-9 of the elastic rows and 1e6 of the dielectric ones).
constexpr double kStrongShare = 1e-3;
// Scales beyond this range of the component's first row are refused: the weighted matrix would have
// entries near the ends of the double range (a constant convection on a fine grid grows geometrically).
constexpr double kLargestScale = 1e100;

}  // namespace

RowSymmetrizer::RowSymmetrizer(const CsrMatrix& pattern) : rows_(pattern.rows()), nonzeros_(pattern.nonZeros()) {
  require(pattern.isCompressed() && pattern.rows() == pattern.cols(),
          "RowSymmetrizer: needs a compressed square matrix, not ", pattern.rows(), " x ", pattern.cols());
  mirror_.resize(pattern.nonZeros());
  for (int i = 0; i < pattern.rows(); ++i)
    for (int k = pattern.outerIndexPtr()[i]; k < pattern.outerIndexPtr()[i + 1]; ++k) {
      mirror_[k] = find_slot(pattern, pattern.innerIndexPtr()[k], i);
      if (mirror_[k] < 0) {
        mirror_.clear();
        return;
      }
    }
}

bool RowSymmetrizer::has_pattern(const CsrMatrix& a) const {
  return a.isCompressed() && a.rows() == rows_ && a.cols() == rows_ && a.nonZeros() == nonzeros_;
}

std::optional<Eigen::VectorXd> RowSymmetrizer::scale(const CsrMatrix& a, double tolerance) const {
  require(has_pattern(a), "RowSymmetrizer: the matrix (", a.rows(), " x ", a.cols(), ", ", a.nonZeros(),
          " entries) does not have the pattern it was made for (", rows_, " rows, ", nonzeros_, " entries)");
  if (mirror_.empty() && nonzeros_ > 0) return std::nullopt;
  const int n = int(a.rows());
  const int* start = a.outerIndexPtr();
  const int* column = a.innerIndexPtr();
  const double* value = a.valuePtr();
  const std::vector<int>& mirror = mirror_;
  std::vector<double> row_max(n, 0);
  for (int i = 0; i < n; ++i)
    for (int k = start[i]; k < start[i + 1]; ++k) {
      if (!std::isfinite(value[k])) return std::nullopt;
      row_max[i] = std::max(row_max[i], std::abs(value[k]));
    }

  // Breadth-first through strong pairs, s_j = s_i A_ij / A_ji; a row not reached starts a component.
  Eigen::VectorXd s = Eigen::VectorXd::Zero(n);
  std::vector<int> queue;
  queue.reserve(n);
  auto strong = [&](int i, int k) {
    const int j = column[k];
    return value[k] != 0 && value[mirror[k]] != 0 &&
           (std::abs(value[k]) >= kStrongShare * row_max[i] || std::abs(value[mirror[k]]) >= kStrongShare * row_max[j]);
  };
  for (int root = 0; root < n; ++root) {
    if (s[root] != 0) continue;
    s[root] = 1;
    queue.assign(1, root);
    for (size_t head = 0; head < queue.size(); ++head) {
      const int i = queue[head];
      for (int k = start[i]; k < start[i + 1]; ++k) {
        const int j = column[k];
        if (s[j] != 0 || !strong(i, k)) continue;
        s[j] = s[i] * value[k] / value[mirror[k]];
        if (!(std::abs(s[j]) <= kLargestScale && std::abs(s[j]) >= 1 / kLargestScale)) return std::nullopt;
        queue.push_back(j);
      }
    }
  }
  for (int i = 0; i < n; ++i)
    for (int k = start[i]; k < start[i + 1]; ++k) {
      const int j = column[k];
      if (j <= i) continue;
      const double gap = std::abs(s[i] * value[k] - s[j] * value[mirror[k]]);
      if (gap > tolerance * std::max(std::abs(s[i]) * row_max[i], std::abs(s[j]) * row_max[j])) return std::nullopt;
    }
  return s;
}

std::optional<Eigen::VectorXd> symmetrizing_row_scale(const CsrMatrix& a, double tolerance) {
  return RowSymmetrizer(a).scale(a, tolerance);
}

}  // namespace pc
