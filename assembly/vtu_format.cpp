#include "assembly/vtu_format.hpp"

#include "assembly/error.hpp"

namespace pc {

namespace {
constexpr VtuFormat kFormats[] = {VtuFormat::Ascii, VtuFormat::Base64, VtuFormat::Binary, VtuFormat::Zlib};
}  // namespace

std::string to_string(VtuFormat format) {
  switch (format) {
    case VtuFormat::Ascii: return "ascii";
    case VtuFormat::Base64: return "base64";
    case VtuFormat::Binary: return "binary";
    case VtuFormat::Zlib: return "zlib";
  }
  fail("to_string: no VTU format ", static_cast<int>(format));
}

std::vector<std::string> vtu_format_names() {
  std::vector<std::string> names;
  for (const VtuFormat f : kFormats) names.push_back(to_string(f));
  return names;
}

VtuFormat vtu_format_from_name(const std::string& name, const std::string& where) {
  std::string known;
  for (const VtuFormat f : kFormats) {
    if (to_string(f) == name) return f;
    known += (known.empty() ? "" : ", ") + to_string(f);
  }
  fail(where, ": unknown VTU format '", name, "' (known: ", known, ")");
}

}  // namespace pc
