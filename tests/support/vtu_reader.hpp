#pragma once
// Test support: reading back the inline binary (base64) DataArrays of a .vtu text that VtuWriter wrote.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace pc::testing {

inline std::string base64_decode(const std::string& text) {
  auto sextet = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::string bytes;
  std::uint32_t group = 0;
  int bits = 0;
  for (char c : text) {
    const int value = sextet(c);
    if (value < 0) continue;  // padding and whitespace
    group = (group << 6) | std::uint32_t(value);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      bytes.push_back(static_cast<char>((group >> bits) & 0xff));
    }
  }
  return bytes;
}

inline std::uint64_t little_endian(const std::string& bytes, size_t at, int size) {
  std::uint64_t value = 0;
  for (int b = size - 1; b >= 0; --b) value = (value << 8) | static_cast<unsigned char>(bytes[at + b]);
  return value;
}

struct DataArray {
  std::string type;
  int components = 0;
  std::string bytes;  // decoded payload without the UInt64 header

  std::vector<double> doubles() const {
    std::vector<double> values(bytes.size() / 8);
    for (size_t i = 0; i < values.size(); ++i) {
      const std::uint64_t bits = little_endian(bytes, 8 * i, 8);
      std::memcpy(&values[i], &bits, 8);
    }
    return values;
  }
  std::vector<std::int64_t> int64s() const {
    std::vector<std::int64_t> values(bytes.size() / 8);
    for (size_t i = 0; i < values.size(); ++i) values[i] = std::int64_t(little_endian(bytes, 8 * i, 8));
    return values;
  }
};

inline std::string attribute(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const size_t start = tag.find(key);
  if (start == std::string::npos) return "";
  const size_t begin = start + key.size();
  return tag.substr(begin, tag.find('"', begin) - begin);
}

// The array of the given name inside the element <section> ... </section> of a .vtu text.
inline DataArray find_array(const std::string& vtu, const std::string& section, const std::string& name) {
  const size_t section_begin = vtu.find("<" + section + ">");
  const size_t section_end = vtu.find("</" + section + ">");
  if (section_begin == std::string::npos || section_end == std::string::npos) {
    ADD_FAILURE() << "no section " << section;
    return {};
  }
  const size_t name_at = vtu.find("Name=\"" + name + "\"", section_begin);
  if (name_at == std::string::npos || name_at > section_end) {
    ADD_FAILURE() << "no array " << name << " in " << section;
    return {};
  }
  const size_t tag_begin = vtu.rfind("<DataArray", name_at);
  const size_t tag_end = vtu.find('>', name_at);
  const std::string tag = vtu.substr(tag_begin, tag_end - tag_begin);
  EXPECT_EQ(attribute(tag, "format"), "binary");
  const size_t data_end = vtu.find("</DataArray>", tag_end);
  const std::string decoded = base64_decode(vtu.substr(tag_end + 1, data_end - tag_end - 1));

  DataArray array;
  array.type = attribute(tag, "type");
  array.components = std::stoi(attribute(tag, "NumberOfComponents"));
  EXPECT_GE(decoded.size(), 8u);
  EXPECT_EQ(little_endian(decoded, 0, 8), decoded.size() - 8) << "header byte count of " << name;
  array.bytes = decoded.substr(8);
  return array;
}

}  // namespace pc::testing
