#pragma once
// Test support: an independent reader of the DataArrays of a .vtu text, written from the VTK XML format
// (not from VtuWriter's code) for every format VtuWriter writes: format="ascii" (text), "binary" (inline
// base64 of a UInt64 byte count and the values) and "appended" (offset into <AppendedData encoding="raw">,
// after its '_': a UInt64 byte count and the values, or with compressor="vtkZLibDataCompressor" the
// UInt64 header [blocks][block size][last partial block size][compressed sizes] and the zlib blocks).
// Any departure from the format is a test failure.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <sstream>
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

inline void append_little_endian(std::string& bytes, std::uint64_t value, int size) {
  for (int b = 0; b < size; ++b) bytes.push_back(static_cast<char>((value >> (8 * b)) & 0xff));
}

struct DataArray {
  std::string type;
  std::string format;  // the DataArray's format attribute: ascii, binary or appended
  int components = 0;
  std::string bytes;  // the values, little-endian, without any header

  std::vector<double> doubles() const {
    EXPECT_EQ(type, "Float64");
    std::vector<double> values(bytes.size() / 8);
    for (size_t i = 0; i < values.size(); ++i) {
      const std::uint64_t bits = little_endian(bytes, 8 * i, 8);
      std::memcpy(&values[i], &bits, 8);
    }
    return values;
  }
  std::vector<std::int64_t> int64s() const {
    EXPECT_EQ(type, "Int64");
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

// The XML part of a file: everything before the appended data, which may hold any bytes.
inline std::string xml_part(const std::string& vtu) { return vtu.substr(0, vtu.find("<AppendedData")); }

// An attribute of the first element of that name ("VTKFile", "compressor").
inline std::string element_attribute(const std::string& vtu, const std::string& element, const std::string& name) {
  const std::string xml = xml_part(vtu);
  const size_t begin = xml.find("<" + element + " ");
  if (begin == std::string::npos) return "";
  return attribute(xml.substr(begin, xml.find('>', begin) - begin), name);
}

// The Name of every DataArray inside <section> ... </section>, in file order.
inline std::vector<std::string> array_names(const std::string& vtu, const std::string& section) {
  const std::string xml = xml_part(vtu);
  const size_t begin = xml.find("<" + section + ">"), end = xml.find("</" + section + ">");
  std::vector<std::string> names;
  if (begin == std::string::npos || end == std::string::npos) return names;
  for (size_t at = xml.find("<DataArray", begin); at < end; at = xml.find("<DataArray", at + 1))
    names.push_back(attribute(xml.substr(at, xml.find('>', at) - at), "Name"));
  return names;
}

// Text values of a format="ascii" array as little-endian bytes of their type.
inline std::string ascii_bytes(const std::string& text, const std::string& type) {
  std::istringstream in(text);
  std::string bytes, token;
  while (in >> token) {
    if (type == "Float64") {
      char* end = nullptr;
      const double value = std::strtod(token.c_str(), &end);
      EXPECT_EQ(*end, '\0') << "not a number: " << token;
      std::uint64_t bits;
      std::memcpy(&bits, &value, 8);
      append_little_endian(bytes, bits, 8);
    } else {
      char* end = nullptr;
      const long long value = std::strtoll(token.c_str(), &end, 10);
      EXPECT_EQ(*end, '\0') << "not an integer: " << token;
      append_little_endian(bytes, std::uint64_t(value), type == "UInt8" ? 1 : 8);
    }
  }
  return bytes;
}

// The values of the appended array at `offset` after the '_' of <AppendedData>.
inline std::string appended_bytes(const std::string& vtu, size_t offset, bool zlib, const std::string& name) {
  const size_t element = vtu.find("<AppendedData");
  if (element == std::string::npos) {
    ADD_FAILURE() << "array " << name << " is appended, but the file has no <AppendedData>";
    return {};
  }
  const size_t tag_end = vtu.find('>', element);
  EXPECT_EQ(attribute(vtu.substr(element, tag_end - element), "encoding"), "raw");
  const size_t underscore = vtu.find('_', tag_end);
  EXPECT_EQ(vtu.find_first_not_of(" \n\t\r", tag_end + 1), underscore) << "only whitespace before the '_'";
  const size_t data = underscore + 1 + offset;
  if (data + 8 > vtu.size()) {
    ADD_FAILURE() << "array " << name << ": offset " << offset << " is past the end of the file";
    return {};
  }
  if (!zlib) {
    const std::uint64_t size = little_endian(vtu, data, 8);
    EXPECT_LE(data + 8 + size, vtu.size()) << "array " << name;
    return vtu.substr(data + 8, size);
  }
  const std::uint64_t blocks = little_endian(vtu, data, 8);
  const std::uint64_t block_size = little_endian(vtu, data + 8, 8);
  const std::uint64_t last_size = little_endian(vtu, data + 16, 8);
  EXPECT_GT(block_size, 0u) << name;
  EXPECT_LT(last_size, block_size) << name << ": the last block's size is 0 when it is full";
  std::string bytes;
  size_t at = data + 24 + 8 * blocks;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t compressed = little_endian(vtu, data + 24 + 8 * b, 8);
    const std::uint64_t expected = b + 1 == blocks && last_size != 0 ? last_size : block_size;
    std::string block(expected, '\0');
    uLongf produced = uLongf(expected);
    EXPECT_LE(at + compressed, vtu.size()) << name << " block " << b;
    const int status = uncompress(reinterpret_cast<Bytef*>(block.data()), &produced,
                                  reinterpret_cast<const Bytef*>(vtu.data() + at), uLong(compressed));
    EXPECT_EQ(status, Z_OK) << name << " block " << b;
    EXPECT_EQ(produced, expected) << name << " block " << b;
    bytes += block.substr(0, produced);
    at += compressed;
  }
  return bytes;
}

// The array of the given name inside the element <section> ... </section> of a .vtu text.
inline DataArray find_array(const std::string& vtu, const std::string& section, const std::string& name) {
  const std::string xml = xml_part(vtu);
  const size_t section_begin = xml.find("<" + section + ">");
  const size_t section_end = xml.find("</" + section + ">");
  if (section_begin == std::string::npos || section_end == std::string::npos) {
    ADD_FAILURE() << "no section " << section;
    return {};
  }
  const size_t name_at = xml.find("Name=\"" + name + "\"", section_begin);
  if (name_at == std::string::npos || name_at > section_end) {
    ADD_FAILURE() << "no array " << name << " in " << section;
    return {};
  }
  const size_t tag_begin = xml.rfind("<DataArray", name_at);
  const size_t tag_end = xml.find('>', name_at);
  const std::string tag = xml.substr(tag_begin, tag_end - tag_begin);
  EXPECT_EQ(element_attribute(vtu, "VTKFile", "header_type"), "UInt64");
  EXPECT_EQ(element_attribute(vtu, "VTKFile", "byte_order"), "LittleEndian");
  const std::string compressor = element_attribute(vtu, "VTKFile", "compressor");
  EXPECT_TRUE(compressor.empty() || compressor == "vtkZLibDataCompressor") << compressor;

  DataArray array;
  array.type = attribute(tag, "type");
  array.format = attribute(tag, "format");
  array.components = std::stoi(attribute(tag, "NumberOfComponents"));
  const auto content = [&] { return xml.substr(tag_end + 1, xml.find("</DataArray>", tag_end) - tag_end - 1); };
  if (array.format == "ascii") {
    array.bytes = ascii_bytes(content(), array.type);
  } else if (array.format == "binary") {
    EXPECT_TRUE(compressor.empty()) << "inline compressed arrays are not read here";
    const std::string decoded = base64_decode(content());
    EXPECT_GE(decoded.size(), 8u);
    EXPECT_EQ(little_endian(decoded, 0, 8), decoded.size() - 8) << "header byte count of " << name;
    array.bytes = decoded.substr(8);
  } else if (array.format == "appended") {
    EXPECT_EQ(tag.back(), '/') << "an appended DataArray has no content";
    array.bytes = appended_bytes(vtu, std::stoull(attribute(tag, "offset")), !compressor.empty(), name);
  } else {
    ADD_FAILURE() << "array " << name << ": unknown format '" << array.format << "'";
  }
  return array;
}

}  // namespace pc::testing
