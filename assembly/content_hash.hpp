#pragma once
// FNV-1a, 64 bits, over bytes: a fingerprint that tells two contents apart (a damaged checkpoint, a scene
// that changed between a run and its resume). Not a cryptographic hash.
#include <cstdint>
#include <string_view>

namespace pc {

inline std::uint64_t content_hash(std::string_view bytes, std::uint64_t hash = 1469598103934665603ull) {
  for (const char c : bytes) hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  return hash;
}

}  // namespace pc
