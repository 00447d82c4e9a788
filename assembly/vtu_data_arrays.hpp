#pragma once
// The DataArray elements of a VTK XML file in one VtuFormat (assembly/vtu_format.hpp), as the VTK file
// format specifies them with header_type="UInt64":
//   ascii   the values as text;
//   base64  format="binary": base64 of [byte count][values], one stream;
//   binary  format="appended" offset=N: at N bytes after the '_' of <AppendedData encoding="raw">,
//           [byte count][values];
//   zlib    format="appended" offset=N, the file's compressor="vtkZLibDataCompressor": at N,
//           [number of blocks][block size][size of the last, partial block or 0][compressed size of each
//           block], then the blocks, each compressed on its own by zlib (compress2). Sizes before
//           compression are of the values' bytes, all blocks but a partial last one are 32 KiB.
// Counts and sizes are UInt64, everything binary is little-endian.
#include <cstdint>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "assembly/vtu_format.hpp"

namespace pc {

class VtuDataArrays {
 public:
  explicit VtuDataArrays(VtuFormat format) : format_(format) {}

  // The attributes of <VTKFile> that say how the arrays read: version, byte order, header type and, for
  // zlib, the compressor.
  std::string file_attributes() const;

  // Writes one <DataArray> element. An appended format writes the values in write_appended(), raw ones
  // from the caller's memory: the values must outlive that call.
  void add(std::ostream& out, const std::string& name, int components, std::span<const double> values);
  void add(std::ostream& out, const std::string& name, int components, std::span<const std::int64_t> values);
  void add(std::ostream& out, const std::string& name, int components, std::span<const std::uint8_t> values);

  // The <AppendedData> element of the arrays added, to go after </UnstructuredGrid>; nothing for an inline
  // format.
  void write_appended(std::ostream& out) const;

 private:
  template <class Value>
  void add_values(std::ostream& out, const std::string& name, int components, std::span<const Value> values);

  // An appended array: its header (byte count, or zlib's block header), then its bytes, the caller's
  // values as they are or what is kept here (compressed, or byte-swapped on a big-endian host).
  struct Appended {
    std::string header;
    std::string kept;
    std::string_view values;
    std::string_view bytes() const { return kept.empty() ? values : std::string_view(kept); }
  };

  VtuFormat format_;
  std::vector<Appended> appended_;
  std::uint64_t appended_bytes_ = 0;  // so far, without the leading '_': the next array's offset
};

// Text escaped for an XML attribute value.
std::string xml_escape(const std::string& text);

}  // namespace pc
