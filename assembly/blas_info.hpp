#pragma once
// Which BLAS this process runs: the library Debian's alternatives resolved libblas.so.3 to, and, for
// OpenBLAS, the kernel family it chose for this CPU (or the one OPENBLAS_CORETYPE forced). Two machines
// whose kernels differ (OpenBLAS falls back to Prescott on a CPU it does not know) round the factorisations
// and products differently, so their results agree to round-off, not to the bit; this tells which.
#include <string>

namespace pc {

struct BlasInfo {
  std::string library;  // the shared object that holds dgemm_ (its path), or "unknown"
  std::string vendor;   // "OpenBLAS" when its own entry points are there, else "reference or other"
  std::string core;     // OpenBLAS's openblas_get_corename(), e.g. "Haswell"; empty for another BLAS
  std::string config;   // OpenBLAS's openblas_get_config() (version and build options); empty otherwise

  // One line for a log or --version: "OpenBLAS (core Haswell, OpenBLAS 0.3.21 ...) from /usr/lib/...".
  std::string describe() const;
};

// Looked up once, from the symbols this process has loaded.
const BlasInfo& blas_info();

}  // namespace pc
