#include "assembly/dense_inverse.hpp"

#include <cmath>
#include <cstddef>
#include <vector>

#include "assembly/error.hpp"

extern "C" {
// LAPACK (Fortran): a character argument's length is passed last, by value.
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* pivots, int* info);
void dgecon_(const char* norm, const int* n, const double* a, const int* lda, const double* anorm, double* rcond,
             double* work, int* iwork, int* info, std::size_t norm_length);
void dgetri_(const int* n, double* a, const int* lda, const int* pivots, double* work, const int* lwork, int* info);
}

namespace pc {

std::optional<Eigen::MatrixXd> inverse_if_regular(Eigen::MatrixXd a, double smallest) {
  require(a.rows() == a.cols(), "inverse_if_regular: the matrix is ", a.rows(), " x ", a.cols(), ", not square");
  const int n = int(a.rows());
  if (n == 0) return a;
  if (!a.allFinite()) return std::nullopt;
  const double norm = a.cwiseAbs().colwise().sum().maxCoeff();
  std::vector<int> pivots(n);
  int info = 0;
  dgetrf_(&n, &n, a.data(), &n, pivots.data(), &info);
  require(info >= 0, "inverse_if_regular: dgetrf refused argument ", -info);
  if (info > 0) return std::nullopt;  // U(info, info) is exactly zero
  double rcond = 0;
  std::vector<double> work(std::size_t(4) * n);
  std::vector<int> iwork(n);
  dgecon_("1", &n, a.data(), &n, &norm, &rcond, work.data(), iwork.data(), &info, 1);
  require(info == 0, "inverse_if_regular: dgecon refused argument ", -info);
  if (!(std::isfinite(rcond) && rcond * norm > smallest)) return std::nullopt;
  int lwork = -1;
  double best = 0;
  dgetri_(&n, a.data(), &n, pivots.data(), &best, &lwork, &info);
  lwork = std::max(n, int(best));
  work.resize(std::size_t(lwork));
  dgetri_(&n, a.data(), &n, pivots.data(), work.data(), &lwork, &info);
  if (info != 0 || !a.allFinite()) return std::nullopt;
  return a;
}

}  // namespace pc
