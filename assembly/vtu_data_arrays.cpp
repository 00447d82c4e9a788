#include "assembly/vtu_data_arrays.hpp"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <string_view>
#include <type_traits>

#include "assembly/error.hpp"

namespace pc {
namespace {

// VTK's own writer compresses blocks of this size; its readers take any.
constexpr std::uint64_t kBlockBytes = 32768;
// zlib's fastest level: on the paper scene's files (240 x 80) it gives 3.79 MB of 6.36 MB where the default
// level 6 gives 3.73 MB, in about half the time. The doubles of a solution hardly compress at any level;
// what does is their zeros (the z of 2D points and vectors), the connectivity and the offsets.
constexpr int kZlibLevel = 1;

template <class Value> constexpr const char* vtk_type() {
  if constexpr (std::is_same_v<Value, double>)
    return "Float64";
  else if constexpr (std::is_same_v<Value, std::int64_t>)
    return "Int64";
  else
    return "UInt8";
}

// The values' bytes, little-endian whatever the host: their own memory on a little-endian host, else a
// byte-swapped copy in `scratch`.
template <class Value>
std::string_view little_endian_bytes(std::span<const Value> values, [[maybe_unused]] std::string& scratch) {
  if (values.empty()) return {};
  const std::string_view own(reinterpret_cast<const char*>(values.data()), values.size_bytes());
  if constexpr (std::endian::native == std::endian::little || sizeof(Value) == 1) {
    return own;
  } else {
    scratch.assign(own);
    for (size_t i = 0; i < scratch.size(); i += sizeof(Value))
      std::reverse(scratch.begin() + i, scratch.begin() + i + sizeof(Value));
    return scratch;
  }
}

void append_uint64(std::string& bytes, std::uint64_t value) {
  for (int b = 0; b < 8; ++b) bytes.push_back(static_cast<char>((value >> (8 * b)) & 0xff));
}

std::string base64(std::string_view bytes) {
  static constexpr char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  text.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const size_t n = std::min<size_t>(3, bytes.size() - i);
    std::uint32_t group = 0;
    for (size_t k = 0; k < 3; ++k) group = (group << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (size_t k = 0; k < 4; ++k) text.push_back(k <= n ? alphabet[(group >> (18 - 6 * k)) & 0x3f] : '=');
  }
  return text;
}

// One tuple per line. Doubles in their shortest round-trip form, so that the text reads back bit for bit.
template <class Value> std::string ascii(std::span<const Value> values, int components) {
  std::string text;
  text.reserve(values.size() * (std::is_floating_point_v<Value> ? 16 : 4));
  char number[32];
  for (size_t i = 0; i < values.size(); ++i) {
    std::to_chars_result written;
    if constexpr (std::is_floating_point_v<Value>)
      written = std::to_chars(number, number + sizeof number, values[i]);
    else
      written = std::to_chars(number, number + sizeof number, static_cast<std::int64_t>(values[i]));
    text.append(number, written.ptr);
    text.push_back((i + 1) % size_t(components) == 0 ? '\n' : ' ');
  }
  return text;
}

// The zlib layout of the header comment: the header into `header`, the compressed blocks into `blocks`.
void compress_blocks(std::string_view bytes, std::string& header, std::string& blocks, const std::string& name) {
  const std::uint64_t size = bytes.size();
  const std::uint64_t count = (size + kBlockBytes - 1) / kBlockBytes;
  append_uint64(header, count);
  append_uint64(header, kBlockBytes);
  append_uint64(header, size % kBlockBytes);
  for (std::uint64_t b = 0; b < count; ++b) {
    const uLong block_size = uLong(std::min(kBlockBytes, size - b * kBlockBytes));
    uLongf compressed = compressBound(block_size);
    const size_t at = blocks.size();
    blocks.resize(at + compressed);
    const int status =
        compress2(reinterpret_cast<Bytef*>(blocks.data() + at), &compressed,
                  reinterpret_cast<const Bytef*>(bytes.data() + b * kBlockBytes), block_size, kZlibLevel);
    require(status == Z_OK, "VtuWriter: zlib could not compress array '", name, "' (zlib status ", status, ")");
    blocks.resize(at + compressed);
    append_uint64(header, compressed);
  }
}

}  // namespace

std::string VtuDataArrays::file_attributes() const {
  std::string attributes = "version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\"";
  if (format_ == VtuFormat::Zlib) attributes += " compressor=\"vtkZLibDataCompressor\"";
  return attributes;
}

template <class Value>
void VtuDataArrays::add_values(std::ostream& out, const std::string& name, int components,
                               std::span<const Value> values) {
  require(components >= 1, "VtuWriter: array '", name, "' needs at least one component, got ", components);
  out << "        <DataArray type=\"" << vtk_type<Value>() << "\" Name=\"" << xml_escape(name)
      << "\" NumberOfComponents=\"" << components << "\" format=\"";
  std::string scratch;
  switch (format_) {
    case VtuFormat::Ascii: out << "ascii\">\n" << ascii(values, components) << "        </DataArray>\n"; return;
    case VtuFormat::Base64: {
      // Header and values are one base64 stream: VTK decodes them together when uncompressed.
      std::string bytes;
      append_uint64(bytes, values.size_bytes());
      bytes.append(little_endian_bytes(values, scratch));
      out << "binary\">\n          " << base64(bytes) << "\n        </DataArray>\n";
      return;
    }
    case VtuFormat::Binary:
    case VtuFormat::Zlib: {
      out << "appended\" offset=\"" << appended_bytes_ << "\"/>\n";
      Appended array;
      const std::string_view bytes = little_endian_bytes(values, scratch);
      if (format_ == VtuFormat::Zlib) {
        compress_blocks(bytes, array.header, array.kept, name);
      } else {
        append_uint64(array.header, bytes.size());
        // The caller's own memory is written as it is; a byte-swapped copy is kept.
        if (scratch.empty())
          array.values = bytes;
        else
          array.kept = std::move(scratch);
      }
      appended_bytes_ += array.header.size() + array.bytes().size();
      appended_.push_back(std::move(array));
      return;
    }
  }
}

void VtuDataArrays::add(std::ostream& out, const std::string& name, int components, std::span<const double> values) {
  add_values(out, name, components, values);
}
void VtuDataArrays::add(std::ostream& out, const std::string& name, int components,
                        std::span<const std::int64_t> values) {
  add_values(out, name, components, values);
}
void VtuDataArrays::add(std::ostream& out, const std::string& name, int components,
                        std::span<const std::uint8_t> values) {
  add_values(out, name, components, values);
}

void VtuDataArrays::write_appended(std::ostream& out) const {
  if (format_ != VtuFormat::Binary && format_ != VtuFormat::Zlib) return;
  // The data start right after the '_'; offsets count from there.
  out << "  <AppendedData encoding=\"raw\">\n   _";
  for (const Appended& array : appended_) {
    out.write(array.header.data(), std::streamsize(array.header.size()));
    out.write(array.bytes().data(), std::streamsize(array.bytes().size()));
  }
  out << "\n  </AppendedData>\n";
}

std::string xml_escape(const std::string& text) {
  std::string escaped;
  for (char c : text) {
    switch (c) {
      case '&': escaped += "&amp;"; break;
      case '<': escaped += "&lt;"; break;
      case '>': escaped += "&gt;"; break;
      case '"': escaped += "&quot;"; break;
      case '\'': escaped += "&apos;"; break;
      default: escaped.push_back(c);
    }
  }
  return escaped;
}

}  // namespace pc
