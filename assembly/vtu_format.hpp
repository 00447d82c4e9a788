#pragma once
// How a .vtu file holds its arrays (VTK XML, all of them read by ParaView):
//   ascii   text, each value in the shortest form that reads back as the same double: readable, largest
//   base64  inline binary (format="binary"), base64 text inside each DataArray: the file stays well-formed XML
//   binary  raw appended data (<AppendedData encoding="raw">), a UInt64 byte count before each array
//   zlib    raw appended data, each array compressed by zlib in 32 KiB blocks (vtkZLibDataCompressor)
// Every binary format is little-endian with UInt64 headers, and every format holds the exact doubles.
#include <string>
#include <vector>

namespace pc {

enum class VtuFormat { Ascii, Base64, Binary, Zlib };

// What a writer (and a scene, output.vtu_format) uses unless told otherwise, chosen by measurement on the
// paper scene at 240 x 80 (docs/scenes.md, "VTU formats"): raw binary writes a file of 6.4 MB in about
// 2 ms of CPU time, zlib one of 3.7 MB in about 70 ms; over the 21 files of a run the VTU output then
// takes about 2 % of the run with binary, about 12 % with zlib, more than a budget of 10 %.
inline constexpr VtuFormat kDefaultVtuFormat = VtuFormat::Binary;

// "ascii", "base64", "binary", "zlib".
std::string to_string(VtuFormat format);
// Every format's name, in the enum's order.
std::vector<std::string> vtu_format_names();
// The format of that name; throws "<where>: unknown VTU format 'x' (known: ascii, base64, binary, zlib)".
VtuFormat vtu_format_from_name(const std::string& name, const std::string& where);

}  // namespace pc
