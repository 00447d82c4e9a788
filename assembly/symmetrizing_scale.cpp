#include "assembly/symmetrizing_scale.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "assembly/error.hpp"
#include "assembly/processes.hpp"

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
  return scale(a, tolerance, nullptr);
}

std::optional<Eigen::VectorXd> RowSymmetrizer::scale(const CsrMatrix& a, double tolerance,
                                                     std::vector<int>* component) const {
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
  if (component) component->assign(size_t(n), -1);
  for (int root = 0; root < n; ++root) {
    if (s[root] != 0) continue;
    s[root] = 1;
    queue.assign(1, root);
    for (size_t head = 0; head < queue.size(); ++head) {
      const int i = queue[head];
      if (component) (*component)[size_t(i)] = root;
      for (int k = start[i]; k < start[i + 1]; ++k) {
        const int j = column[k];
        if (s[j] != 0 || !strong(i, k)) continue;
        s[j] = s[i] * value[k] / value[mirror[k]];
        if (!(std::abs(s[j]) <= kLargestScale && std::abs(s[j]) >= 1 / kLargestScale)) return std::nullopt;
        queue.push_back(j);
      }
    }
  }
  if (!symmetric_with(a, s, tolerance, row_max)) return std::nullopt;
  return s;
}

bool RowSymmetrizer::symmetric_with(const CsrMatrix& a, const Eigen::VectorXd& s, double tolerance) const {
  const int n = int(a.rows());
  std::vector<double> row_max(n, 0);
  for (int i = 0; i < n; ++i)
    for (int k = a.outerIndexPtr()[i]; k < a.outerIndexPtr()[i + 1]; ++k)
      row_max[i] = std::max(row_max[i], std::abs(a.valuePtr()[k]));
  return symmetric_with(a, s, tolerance, row_max);
}

bool RowSymmetrizer::symmetric_with(const CsrMatrix& a, const Eigen::VectorXd& s, double tolerance,
                                    const std::vector<double>& row_max) const {
  if (mirror_.empty() && nonzeros_ > 0) return false;
  const int n = int(a.rows());
  const int* start = a.outerIndexPtr();
  const int* column = a.innerIndexPtr();
  const double* value = a.valuePtr();
  for (int i = 0; i < n; ++i)
    for (int k = start[i]; k < start[i + 1]; ++k) {
      const int j = column[k];
      if (j <= i) continue;
      const double gap = std::abs(s[i] * value[k] - s[j] * value[mirror_[k]]);
      if (!(gap <= tolerance * std::max(std::abs(s[i]) * row_max[i], std::abs(s[j]) * row_max[j]))) return false;
    }
  return true;
}

std::optional<Eigen::VectorXd> RowSymmetrizer::scale_of_shares(const CsrMatrix& share, double tolerance) const {
  const int n = int(share.rows());
  std::vector<int> component;
  std::optional<Eigen::VectorXd> s = scale(share, tolerance, &component);
  // A row that a share links to another by a strong pair carries that share's view of its scale; each
  // component's is fixed up to a factor, given by its lowest row of the largest |s| (the same field's rows
  // on every process, for the block-wise constant scales of coupled fields).
  std::vector<int> size(size_t(n), 0);
  for (int root : component) ++size[size_t(root)];
  const auto carries = [&](int row) { return size[size_t(component[size_t(row)])] > 1; };
  if (s) {
    std::vector<double> pivot(size_t(n), 0.0);  // by component root
    for (int i = 0; i < n; ++i) {
      double& p = pivot[size_t(component[size_t(i)])];
      if (carries(i) && std::abs((*s)[i]) > std::abs(p) * (1 + tolerance)) p = (*s)[i];
    }
    for (int i = 0; i < n; ++i)
      if (const double p = pivot[size_t(component[size_t(i)])]; p != 0) (*s)[i] /= p;
  }
  // Every process joins the same reductions, found scale or not: the largest of the shares' values and the
  // largest of their negatives (the smallest), row by row, over the shares whose rows carry it.
  constexpr double kNone = -std::numeric_limits<double>::infinity();
  std::vector<double> high(size_t(n), kNone), low(size_t(n), kNone);
  if (s)
    for (int i = 0; i < n; ++i)
      if (carries(i)) high[size_t(i)] = (*s)[i], low[size_t(i)] = -(*s)[i];
  if (processes::any(!s)) return std::nullopt;
  processes::max(high);
  processes::max(low);
  Eigen::VectorXd agreed = Eigen::VectorXd::Ones(n);
  bool agree = true;  // the same rows on every process: the same verdict
  for (int i = 0; i < n && agree; ++i) {
    if (high[size_t(i)] == kNone) continue;  // no share links the row: any scale does
    const double lowest = -low[size_t(i)];
    agree = high[size_t(i)] - lowest <= tolerance * std::max(std::abs(high[size_t(i)]), std::abs(lowest));
    agreed[i] = high[size_t(i)];
  }
  if (!agree) return std::nullopt;
  // The rows a share holds by weak entries only took a scale from the others: each share is checked with
  // the agreed one.
  if (processes::any(!symmetric_with(share, agreed, tolerance))) return std::nullopt;
  return agreed;
}

std::optional<Eigen::VectorXd> symmetrizing_row_scale(const CsrMatrix& a, double tolerance) {
  return RowSymmetrizer(a).scale(a, tolerance);
}

}  // namespace pc
