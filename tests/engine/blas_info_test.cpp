// Which BLAS kernels the process runs (issue 44): two machines agree to the bit only when these agree, so a
// user comparing last digits needs them named, and a forced kernel family must be the one reported.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdlib>
#include <string>

#include "assembly/blas_info.hpp"

namespace pc {
namespace {

// The library that holds dgemm_ is found: MUMPS's factorisations call it, so the process has loaded it.
TEST(BlasInfo, NamesTheLoadedLibrary) {
  const BlasInfo& info = blas_info();
  EXPECT_NE(info.library, "unknown");
  EXPECT_NE(info.describe().find(info.library), std::string::npos) << info.describe();
}

// OpenBLAS names the kernel family it chose; under OPENBLAS_CORETYPE (CI's rounding stage) it is the one
// forced, so the stage really runs other kernels. Another BLAS has no core to name.
TEST(BlasInfo, NamesTheCoreOpenBlasChoseOrWasGiven) {
  const BlasInfo& info = blas_info();
  if (info.vendor != "OpenBLAS") {
    EXPECT_TRUE(info.core.empty()) << info.describe();
    GTEST_SKIP() << "not OpenBLAS: " << info.describe();
  }
  EXPECT_FALSE(info.core.empty());
  EXPECT_NE(info.describe().find("core " + info.core), std::string::npos) << info.describe();
  const char* forced = std::getenv("OPENBLAS_CORETYPE");
  if (forced && *forced) {
    std::string a = forced, b = info.core;
    for (char& c : a) c = char(std::tolower(static_cast<unsigned char>(c)));
    for (char& c : b) c = char(std::tolower(static_cast<unsigned char>(c)));
    EXPECT_EQ(a, b) << "OPENBLAS_CORETYPE=" << forced << " but OpenBLAS runs " << info.core;
  }
}

}  // namespace
}  // namespace pc
