#include "assembly/blas_workspace.hpp"

#include <mutex>

extern "C" void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k,
                       const double* alpha, const double* a, const int* lda, const double* b, const int* ldb,
                       const double* beta, double* c, const int* ldc);

namespace pc {

void reserve_blas_workspace() {
  static std::once_flag once;
  std::call_once(once, [] {
    // Large enough that no small-matrix shortcut of the BLAS skips its buffer.
    constexpr int n = 64;
    static double a[n * n], b[n * n], c[n * n];
    const double one = 1, zero = 0;
    dgemm_("N", "N", &n, &n, &n, &one, a, &n, b, &n, &zero, c, &n);
  });
}

}  // namespace pc
