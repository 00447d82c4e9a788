#include "assembly/blas_info.hpp"

#include <dlfcn.h>

namespace pc {
namespace {

// A function of the loaded BLAS that returns a C string, or an empty string when the BLAS has none.
std::string blas_string(const char* symbol) {
  using Getter = const char* (*)();
  const auto getter = reinterpret_cast<Getter>(dlsym(RTLD_DEFAULT, symbol));
  const char* text = getter ? getter() : nullptr;
  std::string s = text ? text : "";
  while (!s.empty() && (s.back() == ' ' || s.back() == '\n')) s.pop_back();
  return s;
}

// The shared object that defines a symbol, or "unknown".
std::string library_of(void* symbol) {
  Dl_info where{};
  return symbol && dladdr(symbol, &where) && where.dli_fname ? where.dli_fname : "unknown";
}

BlasInfo look_up() {
  BlasInfo info;
  info.core = blas_string("openblas_get_corename");
  info.config = blas_string("openblas_get_config");
  info.vendor = info.core.empty() && info.config.empty() ? "reference or other" : "OpenBLAS";
  // dgemm_, the BLAS every factorisation and dense product of the run calls: its next definition after
  // this library, which forwards it (assembly/blas_vector_forwarding.hpp). OpenBLAS's own entry point
  // names the same object without that detour.
  void* own = dlsym(RTLD_DEFAULT, "openblas_get_config");
  info.library = library_of(own ? own : dlsym(RTLD_NEXT, "dgemm_"));
  return info;
}

}  // namespace

std::string BlasInfo::describe() const {
  std::string s = vendor;
  if (!core.empty() || !config.empty()) s += " (core " + (core.empty() ? "?" : core) + ", " + config + ")";
  return s + " from " + library;
}

const BlasInfo& blas_info() {
  static const BlasInfo info = look_up();
  return info;
}

}  // namespace pc
