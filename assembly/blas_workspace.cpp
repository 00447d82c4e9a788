#include "assembly/blas_workspace.hpp"

#include <cstddef>
#include <cstdlib>
#include <mutex>
#include <vector>

#include "assembly/error.hpp"

// As Fortran calls it (blas_vector_forwarding.cpp): the lengths of the character arguments at the end.
extern "C" void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k,
                       const double* alpha, const double* a, const int* lda, const double* b, const int* ldb,
                       const double* beta, double* c, const int* ldc, std::size_t, std::size_t);

namespace pc {

void reserve_blas_workspace() {
  static std::once_flag once;
  std::call_once(once, [] {
    // OpenBLAS's buffer (BUFFER_SIZE, 128 MiB on x86-64, and a page): if memory that large cannot be had
    // now, the product below would retry for ever; an error names the shortage instead.
    constexpr std::size_t kBufferBytes = (std::size_t(128) << 20) + (std::size_t(64) << 10);
    void* probe = std::malloc(kBufferBytes);
    if (probe == nullptr)
      throw OutOfMemory(
          "out of memory while reserving the BLAS's work buffer (128 MiB), before the model is built: "
          "free memory, or raise the process's limit (ulimit -v)");
    std::free(probe);
    // Large enough that no small-matrix shortcut of the BLAS skips its buffer: OpenBLAS 0.3.21 takes one
    // below 100^3 multiply-adds on CPUs with its small-matrix kernels (AVX-512), and a 64^3 product
    // reserved nothing there, so the first factorisation under a memory limit hung in the retry.
    constexpr int n = 256;
    std::vector<double> a(n * n, 0.0), b(n * n, 0.0), c(n * n, 0.0);
    const double one = 1, zero = 0;
    dgemm_("N", "N", &n, &n, &n, &one, a.data(), &n, b.data(), &n, &zero, c.data(), &n, 1, 1);
  });
}

}  // namespace pc
