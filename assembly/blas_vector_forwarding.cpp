#include "assembly/blas_vector_forwarding.hpp"

#include <dlfcn.h>

#include <atomic>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <string_view>

// Fortran BLAS, as gfortran calls it: every argument by address, and each character argument's length
// passed at the end (which the C BLAS ignores, but a Fortran one may read).
using Length = std::size_t;
using Dgemm = void (*)(const char*, const char*, const int*, const int*, const int*, const double*, const double*,
                       const int*, const double*, const int*, const double*, double*, const int*, Length, Length);
using Dtrsm = void (*)(const char*, const char*, const char*, const char*, const int*, const int*, const double*,
                       const double*, const int*, double*, const int*, Length, Length, Length, Length);

extern "C" {
void dgemv_(const char* trans, const int* m, const int* n, const double* alpha, const double* a, const int* lda,
            const double* x, const int* incx, const double* beta, double* y, const int* incy, Length);
void dtrsv_(const char* uplo, const char* trans, const char* diag, const int* n, const double* a, const int* lda,
            double* x, const int* incx, Length, Length, Length);
}

namespace {

std::atomic<long> forwarded{0};

// The BLAS's own routine: the next definition after this library's.
template <class Function> Function next_definition(const char* name) {
  void* symbol = dlsym(RTLD_NEXT, name);
  if (symbol == nullptr) {
    std::fprintf(stderr, "piezocontact: no BLAS routine %s after the library's own (dlsym: %s)\n", name, dlerror());
    std::abort();  // called from Fortran: there is no error to return
  }
  return reinterpret_cast<Function>(symbol);
}

bool is(const char* option, char letter) { return *option == letter || *option == letter + ('a' - 'A'); }

// PIEZOCONTACT_BLAS_FORWARDING=0 sends every call to the BLAS's own routine (to measure what forwarding
// gains, or to rule it out).
bool forwarding_wanted() {
  static const bool wanted = [] {
    const char* setting = std::getenv("PIEZOCONTACT_BLAS_FORWARDING");
    return setting == nullptr || std::string_view(setting) != "0";
  }();
  return wanted;
}

}  // namespace

extern "C" {

// C = alpha op(A) op(B) + beta C; with one column (N = 1), op(B) is a vector: C = alpha op(A) b + beta C.
void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k, const double* alpha,
            const double* a, const int* lda, const double* b, const int* ldb, const double* beta, double* c,
            const int* ldc, Length transa_length, Length transb_length) {
  static const Dgemm blas = next_definition<Dgemm>("dgemm_");
  if (*n == 1 && *m > 0 && *k > 0 && forwarding_wanted()) {
    const int b_stride = is(transb, 'N') ? 1 : *ldb, one = 1;
    if (is(transa, 'N'))
      dgemv_("N", m, k, alpha, a, lda, b, &b_stride, beta, c, &one, 1);
    else
      dgemv_("T", k, m, alpha, a, lda, b, &b_stride, beta, c, &one, 1);
    forwarded.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  blas(transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc, transa_length, transb_length);
}

// op(A) X = alpha B (side L) or X op(A) = alpha B (side R); with one column on the left and alpha = 1,
// op(A) x = b.
void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m, const int* n,
            const double* alpha, const double* a, const int* lda, double* b, const int* ldb, Length side_length,
            Length uplo_length, Length transa_length, Length diag_length) {
  static const Dtrsm blas = next_definition<Dtrsm>("dtrsm_");
  if (is(side, 'L') && *n == 1 && *m > 0 && *alpha == 1.0 && forwarding_wanted()) {
    const int one = 1;
    dtrsv_(uplo, transa, diag, m, a, lda, b, &one, 1, 1, 1);
    forwarded.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  blas(side, uplo, transa, diag, m, n, alpha, a, lda, b, ldb, side_length, uplo_length, transa_length, diag_length);
}

}  // extern "C"

namespace pc {

bool blas_vector_forwarding_active() {
  return dlsym(RTLD_DEFAULT, "dgemm_") == reinterpret_cast<void*>(&dgemm_) &&
         dlsym(RTLD_DEFAULT, "dtrsm_") == reinterpret_cast<void*>(&dtrsm_);
}

long blas_vector_forwarded_calls() { return forwarded.load(std::memory_order_relaxed); }

}  // namespace pc
