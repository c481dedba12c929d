// SPDX-License-Identifier: GPL-3.0-or-later
// VTK XML unstructured grid (.vtu) for ParaView: tetrahedra with named
// scalar fields per point and per cell, in ASCII or binary (zlib, from
// Debian's zlib1g-dev), after VTK's "VTK File Formats" documentation.

#ifndef CGAL_EDGE_SWAPPING_3_IO_VTU_H
#define CGAL_EDGE_SWAPPING_3_IO_VTU_H

#include <CGAL/Edge_swapping_3/IO/text_input.h>
#include <CGAL/Edge_swapping_3/IO/text_output.h>
#include <zlib.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <stdexcept>
#include <string_view>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace IO {

/// Arrays of values by name, one value per point or per cell.
typedef std::vector<std::pair<std::string, std::vector<double>>> Named_fields;

namespace internal {

/// `data` as VTK writes a zlib-compressed array: a header of UInt64 words
/// (the number of blocks, the block size, the last block's size, each
/// block's compressed size), then the blocks of at most 32 KiB, compressed.
inline std::string vtk_compressed(std::string_view data)
{
  constexpr std::size_t block = 1 << 15;
  const std::size_t blocks = (data.size() + block - 1) / block;
  std::vector<std::uint64_t> header = {blocks, block, data.size() % block};
  std::string body;
  std::vector<Bytef> buffer(::compressBound(uLong(block)));
  for(std::size_t b = 0; b < blocks; ++b)
  {
    const std::size_t size = (std::min)(block, data.size() - b * block);
    uLongf length = uLongf(buffer.size());
    if(::compress2(buffer.data(), &length, reinterpret_cast<const Bytef*>(data.data() + b * block), uLong(size),
                   Z_DEFAULT_COMPRESSION) != Z_OK)
      throw std::runtime_error("zlib could not compress a data array");
    header.push_back(length);
    body.append(reinterpret_cast<const char*>(buffer.data()), length);
  }
  return std::string(reinterpret_cast<const char*>(header.data()), header.size() * sizeof(std::uint64_t)) + body;
}

template <class T>
std::string_view bytes_of(const std::vector<T>& v)
{
  return std::string_view(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

} // namespace internal

/// \ingroup PkgEdgeSwapping3IO
/// The encodings `write_vtu_file()` writes.
enum Vtu_encoding
{
  VTU_ASCII,      ///< every number as text
  VTU_BINARY_ZLIB ///< as ParaView writes by default: appended raw data, zlib-compressed, UInt64 headers
};

/// \ingroup PkgEdgeSwapping3IO
/// Writes a VTK unstructured grid (`.vtu`) of tetrahedra with point and cell
/// fields, in ASCII or as ParaView writes binary files. Throws
/// `std::domain_error` for a value that is not finite.
inline void write_vtu_file(std::ostream& stream, const std::vector<std::array<double, 3>>& points,
                           const std::vector<std::array<std::size_t, 4>>& tetrahedra,
                           const Named_fields& point_fields, const Named_fields& cell_fields,
                           Vtu_encoding encoding = VTU_ASCII)
{
  const bool binary = encoding == VTU_BINARY_ZLIB;
  Text_sink out(stream); // to_chars: shortest text that reads back the same double
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"" << (binary ? "1.0" : "0.1")
      << "\" byte_order=\"LittleEndian\"" << (binary ? " header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\"" : "")
      << ">\n<UnstructuredGrid>\n"
      << "<Piece NumberOfPoints=\"" << points.size() << "\" NumberOfCells=\"" << tetrahedra.size() << "\">\n";
  // Binary: each array's compressed bytes go to the appended data, the tag names their offset.
  std::string appended;
  auto array = [&](const char* type, const std::string& name, const char* components, std::string_view data,
                   auto write_ascii) {
    out << "<DataArray type=\"" << type << "\"" << (name.empty() ? std::string() : " Name=\"" + name + "\"") << components;
    if(binary)
    {
      out << " format=\"appended\" offset=\"" << appended.size() << "\"/>\n";
      appended += internal::vtk_compressed(data);
      return;
    }
    out << " format=\"ascii\">\n";
    write_ascii();
    out << "</DataArray>\n";
  };
  auto fields = [&](const char* tag, const Named_fields& f) {
    out << "<" << tag << ">\n";
    for(const auto& field : f) // (clang's C++17 does not capture structured bindings)
    {
      const std::vector<double>& values = field.second;
      for(double v : values) finite_value(v, "a value", &field.first);
      array("Float64", field.first, "", internal::bytes_of(values), [&] {
        for(double v : values) out << v << '\n';
      });
    }
    out << "</" << tag << ">\n";
  };
  fields("PointData", point_fields);
  fields("CellData", cell_fields);
  out << "<Points>\n";
  std::vector<double> xyz;
  xyz.reserve(3 * points.size());
  for(const auto& p : points)
    for(double x : p) xyz.push_back(finite_value(x, "a coordinate"));
  array("Float64", "", " NumberOfComponents=\"3\"", internal::bytes_of(xyz), [&] {
    for(std::size_t k = 0; k < xyz.size(); k += 3) out << xyz[k] << ' ' << xyz[k + 1] << ' ' << xyz[k + 2] << '\n';
  });
  out << "</Points>\n<Cells>\n";
  std::vector<std::int64_t> connectivity, offsets;
  if(binary)
  {
    connectivity.reserve(4 * tetrahedra.size());
    for(const auto& t : tetrahedra)
      for(auto v : t) connectivity.push_back(std::int64_t(v));
    for(std::size_t k = 1; k <= tetrahedra.size(); ++k) offsets.push_back(std::int64_t(4 * k));
  }
  const std::vector<std::uint8_t> types(binary ? tetrahedra.size() : 0, std::uint8_t(10)); // VTK_TETRA
  array("Int64", "connectivity", "", internal::bytes_of(connectivity), [&] {
    for(const auto& t : tetrahedra) out << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << t[3] << '\n';
  });
  array("Int64", "offsets", "", internal::bytes_of(offsets), [&] {
    for(std::size_t k = 1; k <= tetrahedra.size(); ++k) out << 4 * k << '\n';
  });
  array("UInt8", "types", "", internal::bytes_of(types), [&] {
    for(std::size_t k = 0; k < tetrahedra.size(); ++k) out << "10\n";
  });
  out << "</Cells>\n</Piece>\n</UnstructuredGrid>\n";
  if(binary) out << "<AppendedData encoding=\"raw\">\n_" << std::string_view(appended) << "\n</AppendedData>\n";
  out << "</VTKFile>\n";
}

/// What `read_vtu_file` returns.
struct Vtu_mesh
{
  std::vector<std::array<double, 3>> points;          ///< the points
  std::vector<std::array<std::size_t, 4>> tetrahedra; ///< 0-based point indices
  Named_fields point_fields;                          ///< the `PointData` arrays of one component
  Named_fields cell_fields;                           ///< the `CellData` arrays of one component
};

namespace internal {

// The attributes of an XML start tag, `name="value"` or `name='value'`;
// `fail(message)` throws.
template <class Fail>
class Xml_attributes
{
public:
  Xml_attributes(std::string_view tag, const Fail& fail) : tag_(tag), where_(fail) {}

  /// The value of attribute `key`, or `none` if the tag has no such attribute.
  std::string_view get(std::string_view key, std::string_view none = std::string_view()) const
  {
    std::size_t at = tag_.find_first_of(" \t\r\n");
    while(at != std::string_view::npos && at < tag_.size())
    {
      at = tag_.find_first_not_of(" \t\r\n/", at);
      if(at == std::string_view::npos) break;
      const std::size_t eq = tag_.find('=', at);
      if(eq == std::string_view::npos) where_("malformed attribute in " + quote_token(tag_));
      std::string_view name = tag_.substr(at, eq - at);
      while(!name.empty() && (name.back() == ' ' || name.back() == '\t')) name.remove_suffix(1);
      const std::size_t open = tag_.find_first_not_of(" \t\r\n", eq + 1);
      if(open == std::string_view::npos || (tag_[open] != '"' && tag_[open] != '\''))
        where_("attribute " + quote_token(name) + " without a quoted value");
      const std::size_t close = tag_.find(tag_[open], open + 1);
      if(close == std::string_view::npos) where_("attribute " + quote_token(name) + " with an unterminated value");
      if(name == key) return tag_.substr(open + 1, close - open - 1);
      at = close + 1;
    }
    return none;
  }

private:
  std::string_view tag_;
  const Fail& where_;
};

/// The bytes that base64 `text` encodes; white space is skipped and each
/// '='-padded group ends a segment, after which another may follow (VTK
/// encodes a binary array's header and its data as two segments). Returns
/// false for a character that is not base64.
inline bool decode_base64(std::string_view text, std::string& bytes)
{
  auto value = [](char c) -> int {
    if(c >= 'A' && c <= 'Z') return c - 'A';
    if(c >= 'a' && c <= 'z') return c - 'a' + 26;
    if(c >= '0' && c <= '9') return c - '0' + 52;
    if(c == '+') return 62;
    if(c == '/') return 63;
    return -1;
  };
  bytes.clear();
  bytes.reserve(text.size() / 4 * 3);
  int group[4], n = 0, pad = 0;
  for(char c : text)
  {
    if(c == ' ' || c == '\n' || c == '\r' || c == '\t') continue;
    if(c == '=') { if(n < 2) return false; group[n++] = 0; ++pad; }
    else
    {
      if(pad > 0) return false; // data after padding inside a group
      const int v = value(c);
      if(v < 0) return false;
      group[n++] = v;
    }
    if(n < 4) continue;
    const unsigned word = unsigned(group[0]) << 18 | unsigned(group[1]) << 12 | unsigned(group[2]) << 6 | unsigned(group[3]);
    bytes.push_back(char(word >> 16));
    if(pad < 2) bytes.push_back(char((word >> 8) & 255));
    if(pad < 1) bytes.push_back(char(word & 255));
    n = pad = 0;
  }
  return n == 0;
}

/// What the attributes of <VTKFile> say of its binary arrays.
struct Vtu_binary_layout
{
  bool header64 = false;   ///< header_type="UInt64" (else UInt32)
  bool compressed = false; ///< compressor="vtkZLibDataCompressor"
};

/// The size in bytes of a VTK data type, 0 for a type not supported.
inline std::size_t vtk_type_size(std::string_view type)
{
  if(type == "Float64" || type == "Int64" || type == "UInt64") return 8;
  if(type == "Float32" || type == "Int32" || type == "UInt32") return 4;
  if(type == "Int16" || type == "UInt16") return 2;
  if(type == "Int8" || type == "UInt8") return 1;
  return 0;
}

/// The value at `p` of VTK type `type` (little-endian), as a double.
inline double vtk_value(std::string_view type, const char* p)
{
  auto get = [p](auto v) {
    std::memcpy(&v, p, sizeof v);
    return double(v);
  };
  if(type == "Float64") return get(double());
  if(type == "Float32") return get(float());
  if(type == "Int64") return get(std::int64_t());
  if(type == "UInt64") return get(std::uint64_t());
  if(type == "Int32") return get(std::int32_t());
  if(type == "UInt32") return get(std::uint32_t());
  if(type == "Int16") return get(std::int16_t());
  if(type == "UInt16") return get(std::uint16_t());
  if(type == "Int8") return get(std::int8_t());
  return get(std::uint8_t());
}

/// The data of a binary array: `bytes` holds its header and its (maybe
/// compressed) blocks, as VTK writes them; `data` gets exactly `expected`
/// bytes, or the returned message says what is wrong. Every size in the
/// header is checked against the bytes there are and against `expected`
/// before anything is allocated or inflated.
inline std::string vtk_binary_data(std::string_view bytes, const Vtu_binary_layout& layout, std::size_t expected,
                                   std::string& data)
{
  const std::size_t word = layout.header64 ? 8 : 4;
  std::size_t at = 0;
  auto header = [&](std::uint64_t& v) {
    if(bytes.size() - at < word) return false;
    if(word == 8) std::memcpy(&v, bytes.data() + at, 8);
    else
    {
      std::uint32_t u;
      std::memcpy(&u, bytes.data() + at, 4);
      v = u;
    }
    at += word;
    return true;
  };
  data.clear();
  if(!layout.compressed)
  {
    std::uint64_t n = 0;
    if(!header(n)) return "the binary data is cut short (no header)";
    if(n != expected) return "the binary data holds " + std::to_string(n) + " bytes, not " + std::to_string(expected);
    if(bytes.size() - at < n) return "the binary data is cut short";
    data.assign(bytes.data() + at, std::size_t(n));
    return std::string();
  }
  std::uint64_t blocks = 0, block_size = 0, last_size = 0;
  if(!header(blocks) || !header(block_size) || !header(last_size)) return "the compression header is cut short";
  if(blocks > (bytes.size() - at) / word) return "the compression header names more blocks than the file holds";
  const std::uint64_t total = blocks == 0 ? 0 : (blocks - 1) * block_size + (last_size == 0 ? block_size : last_size);
  if(blocks > 0 && (block_size == 0 || last_size > block_size || total != expected))
    return "the compressed blocks hold " + std::to_string(total) + " bytes, not " + std::to_string(expected);
  if(blocks == 0 && expected != 0) return "no compressed block, but " + std::to_string(expected) + " bytes are expected";
  // zlib inflates at most 1032 to 1: a larger claim is not what the blocks hold.
  if(expected / 1032 > bytes.size() - at) return "the compressed blocks are too short for " + std::to_string(expected) + " bytes";
  std::vector<std::uint64_t> sizes(static_cast<std::size_t>(blocks));
  for(auto& z : sizes) header(z);
  data.resize(std::size_t(expected));
  std::size_t out = 0;
  for(std::size_t b = 0; b < sizes.size(); ++b)
  {
    if(sizes[b] > bytes.size() - at) return "a compressed block is cut short";
    uLongf length = uLongf(b + 1 == sizes.size() && last_size != 0 ? last_size : block_size);
    const uLongf wanted = length;
    if(::uncompress(reinterpret_cast<Bytef*>(&data[out]), &length, reinterpret_cast<const Bytef*>(bytes.data() + at),
                    uLong(sizes[b])) != Z_OK ||
       length != wanted)
      return "a compressed block is not valid zlib data of the size its header gives";
    at += std::size_t(sizes[b]);
    out += length;
  }
  return std::string();
}

} // namespace internal

/// Reads the text of a .vtu file as VTK and ParaView write it (tetrahedra
/// only, one Piece): data arrays in ASCII, inline binary (base64) or
/// appended (raw or base64), uncompressed or zlib-compressed, with UInt32 or
/// UInt64 headers, little-endian, of any VTK number type. Anything else is
/// an Input_error naming the file, the line and the problem. Linear in the
/// size of the file.
inline Vtu_mesh read_vtu_text(const std::string& name, std::string_view text)
{
  std::size_t line = 1, counted_to = 0;
  auto fail_at = [&](std::size_t pos, const std::string& what) {
    for(; counted_to < pos && counted_to < text.size(); ++counted_to) line += text[counted_to] == '\n';
    throw Input_error(name + ":" + std::to_string(line) + ": " + what);
  };

  enum Section { NONE, POINTS, CELLS, POINT_DATA, CELL_DATA };
  Section section = NONE;
  bool vtk_file = false, piece_seen = false, piece_open = false;
  std::size_t n_points = 0, n_cells = 0;
  std::vector<double> connectivity, offsets, types, coordinates;
  bool have_connectivity = false, have_offsets = false, have_types = false, have_points = false;
  Vtu_mesh m;
  std::unordered_set<std::string> point_names, cell_names;
  auto field_name_ok = [](std::string_view s) {
    if(s.empty() || s.size() > 256) return false;
    for(char ch : s)
      if(ch < 32 || ch >= 127 || ch == '<' || ch == '>' || ch == '&' || ch == '"' || ch == '\'') return false;
    return true;
  };

  // Appended data (binary arrays after the XML, raw or base64) ends the
  // XML part: raw bytes may hold anything, '<' included.
  std::string_view xml = text, appended;
  bool appended_base64 = false;
  if(const std::size_t at = text.find("<AppendedData"); at != std::string_view::npos)
  {
    xml = text.substr(0, at);
    const std::size_t close = text.find('>', at);
    if(close == std::string_view::npos) fail_at(at, "unterminated <AppendedData>");
    auto fail = [&](const std::string& what) { fail_at(at, what); };
    const internal::Xml_attributes<decltype(fail)> attributes(text.substr(at + 1, close - at - 1), fail);
    const std::string_view encoding = attributes.get("encoding");
    if(encoding != "raw" && encoding != "base64") fail("<AppendedData> encoding is " + quote_token(encoding) + ", not raw or base64");
    appended_base64 = encoding == "base64";
    const std::size_t mark = text.find('_', close + 1);
    if(mark == std::string_view::npos) fail("<AppendedData> without the '_' that starts its data");
    appended = text.substr(mark + 1);
    if(appended_base64) appended = appended.substr(0, appended.find('<'));
  }
  internal::Vtu_binary_layout layout;

  std::size_t pos = 0;
  while((pos = xml.find('<', pos)) != std::string_view::npos)
  {
    if(xml.compare(pos, 4, "<!--") == 0)
    {
      const std::size_t end = xml.find("-->", pos + 4);
      if(end == std::string_view::npos) fail_at(pos, "unterminated comment");
      pos = end + 3;
      continue;
    }
    const std::size_t close = xml.find('>', pos);
    if(close == std::string_view::npos) fail_at(pos, "unterminated tag");
    const std::string_view tag = xml.substr(pos + 1, close - pos - 1);
    const std::size_t tag_start = pos;
    pos = close + 1;
    if(!tag.empty() && (tag[0] == '?' || tag[0] == '!')) continue; // declaration
    const bool closing = !tag.empty() && tag[0] == '/';
    const std::string_view body = closing ? tag.substr(1) : tag;
    const std::string_view element = body.substr(0, body.find_first_of(" \t\r\n/"));
    auto fail = [&](const std::string& what) { fail_at(tag_start, what); };
    const internal::Xml_attributes<decltype(fail)> attributes(tag, fail);

    if(element == "VTKFile")
    {
      if(closing) continue;
      if(attributes.get("type") != "UnstructuredGrid") fail("not a VTK unstructured grid (.vtu) file");
      if(attributes.get("byte_order", "LittleEndian") != "LittleEndian")
        fail("byte order " + quote_token(attributes.get("byte_order")) + ": only LittleEndian files are read");
      const std::string_view header = attributes.get("header_type", "UInt32");
      if(header != "UInt32" && header != "UInt64") fail("header_type " + quote_token(header) + " is not UInt32 or UInt64");
      layout.header64 = header == "UInt64";
      const std::string_view compressor = attributes.get("compressor");
      if(!compressor.empty() && compressor != "vtkZLibDataCompressor")
        fail("compressor " + quote_token(compressor) + " is not supported: write with zlib compression or none");
      layout.compressed = !compressor.empty();
      vtk_file = true;
    }
    else if(element == "Piece")
    {
      if(closing) { piece_open = false; continue; }
      if(!vtk_file) fail("<Piece> outside <VTKFile type=\"UnstructuredGrid\">");
      if(piece_seen) fail("more than one <Piece> (only one is supported)");
      piece_seen = piece_open = true;
      long long np = -1, nc = -1;
      if(internal::parse_number(attributes.get("NumberOfPoints"), np) != internal::Number_status::ok ||
         internal::parse_number(attributes.get("NumberOfCells"), nc) != internal::Number_status::ok || np < 0 || nc < 0)
        fail("<Piece> without a whole NumberOfPoints and NumberOfCells");
      // Each point takes at least 6 bytes (3 numbers), each cell 12 (6 numbers); zlib inflates 1032 to 1 at most.
      const std::size_t room = layout.compressed ? 1032 * text.size() : text.size();
      if(std::size_t(np) > room / 6 || std::size_t(nc) > room / 12)
        fail("NumberOfPoints " + std::to_string(np) + " and NumberOfCells " + std::to_string(nc) +
             " are more than the file can hold (" + std::to_string(text.size()) + " bytes)");
      n_points = std::size_t(np);
      n_cells = std::size_t(nc);
    }
    else if(element == "Points" || element == "Cells" || element == "PointData" || element == "CellData")
    {
      if(closing) { section = NONE; continue; }
      if(!piece_open) fail("<" + std::string(element) + "> outside <Piece>");
      if(section != NONE) fail("<" + std::string(element) + "> inside another section");
      section = element == "Points" ? POINTS : element == "Cells" ? CELLS : element == "PointData" ? POINT_DATA : CELL_DATA;
      if(!body.empty() && body.back() == '/') section = NONE; // an empty section: <PointData/>
    }
    else if(element == "DataArray")
    {
      if(closing) fail("</DataArray> without <DataArray>");
      const std::string array_name(attributes.get("Name"));
      if(section == NONE) fail("data array " + quote_token(array_name) + " outside Points, Cells, PointData and CellData");
      const std::string_view format = attributes.get("format");
      if(format != "ascii" && format != "binary" && format != "appended")
        fail("data array " + quote_token(array_name) + " has format " + quote_token(format) + ", not ascii, binary or appended");
      const std::string_view components = attributes.get("NumberOfComponents", section == POINTS ? "3" : "1");
      if(components != (section == POINTS ? "3" : "1"))
        fail("data array " + quote_token(array_name) + " has NumberOfComponents " + quote_token(components));
      // How many values it must hold, and where they go.
      std::vector<double>* values = nullptr;
      std::vector<double> field;
      std::size_t expected = 0;
      if(section == POINTS)
      {
        if(have_points) fail("a second data array in <Points>");
        have_points = true;
        values = &coordinates;
        expected = 3 * n_points;
      }
      else if(section == CELLS)
      {
        bool* have = array_name == "connectivity" ? &have_connectivity : array_name == "offsets" ? &have_offsets
                     : array_name == "types" ? &have_types : nullptr;
        if(have == nullptr) fail("unknown cell array " + quote_token(array_name));
        if(*have) fail("a second " + quote_token(array_name) + " array");
        *have = true;
        values = array_name == "connectivity" ? &connectivity : array_name == "offsets" ? &offsets : &types;
        expected = array_name == "connectivity" ? 4 * n_cells : n_cells;
      }
      else
      {
        if(!field_name_ok(array_name)) fail("field name " + quote_token(array_name) + " is empty, too long or has characters that are not supported");
        if(!(section == POINT_DATA ? point_names : cell_names).insert(array_name).second)
          fail("two fields named " + quote_token(array_name));
        values = &field;
        expected = section == POINT_DATA ? n_points : n_cells;
      }
      // The array's data runs to the next tag; elements such as VTK's
      // <InformationKey> may follow it before </DataArray>.
      const std::size_t data_end = xml.find('<', pos);
      const std::size_t closing_tag = data_end == std::string_view::npos ? data_end : xml.find("</DataArray>", data_end);
      const bool self_closing = !body.empty() && body.back() == '/';
      if(!self_closing && (closing_tag == std::string_view::npos || xml.find("<DataArray", data_end) < closing_tag))
        fail("data array " + quote_token(array_name) + " is not closed by </DataArray>");
      if(format != "ascii")
      {
        const std::string_view type = attributes.get("type");
        const std::size_t size = internal::vtk_type_size(type);
        if(size == 0) fail("data array " + quote_token(array_name) + " has type " + quote_token(type) + ", not a VTK number type");
        std::string decoded, data;
        std::string_view bytes;
        if(format == "binary")
        {
          if(self_closing) fail("data array " + quote_token(array_name) + " has no data");
          if(!internal::decode_base64(xml.substr(pos, data_end - pos), decoded))
            fail("data array " + quote_token(array_name) + " is not valid base64");
          bytes = decoded;
        }
        else
        {
          long long offset = -1;
          if(internal::parse_number(attributes.get("offset"), offset) != internal::Number_status::ok || offset < 0)
            fail("data array " + quote_token(array_name) + " has no whole offset");
          if(std::size_t(offset) > appended.size())
            fail("data array " + quote_token(array_name) + " has offset " + std::to_string(offset) +
                 ", beyond the appended data (" + std::to_string(appended.size()) + " bytes)");
          // An array's base64 ends where the next begins; decoding to the end is linear per array.
          if(appended_base64 && !internal::decode_base64(appended.substr(std::size_t(offset)), decoded))
            fail("the appended data of " + quote_token(array_name) + " is not valid base64");
          bytes = appended_base64 ? std::string_view(decoded) : appended.substr(std::size_t(offset));
        }
        if(!self_closing) pos = closing_tag + 12;
        const std::string problem = internal::vtk_binary_data(bytes, layout, expected * size, data);
        if(!problem.empty()) fail("data array " + quote_token(array_name) + ": " + problem);
        values->resize(expected);
        for(std::size_t k = 0; k < expected; ++k)
        {
          const double d = internal::vtk_value(type, data.data() + k * size);
          if(!std::isfinite(d)) fail("a value of " + quote_token(array_name) + " is not finite");
          (*values)[k] = d;
        }
        if(section == POINT_DATA) m.point_fields.emplace_back(array_name, std::move(field));
        if(section == CELL_DATA) m.cell_fields.emplace_back(array_name, std::move(field));
        continue;
      }
      if(self_closing) fail("data array " + quote_token(array_name) + " has no data");
      values->reserve(expected);
      // The numbers up to the next tag.
      const std::size_t end = data_end;
      for(std::size_t at = pos;;)
      {
        at = xml.find_first_not_of(" \t\r\n", at);
        if(at >= end) break;
        const std::size_t stop = std::min(end, xml.find_first_of(" \t\r\n", at));
        const std::string_view token = xml.substr(at, stop - at);
        at = stop;
        if(values->size() == expected)
          fail("data array " + quote_token(array_name) + " has more than " + std::to_string(expected) + " values");
        double d = 0;
        const auto status = internal::parse_number(token, d);
        if(status != internal::Number_status::ok)
          fail("cannot read a number from " + quote_token(token) + " in " + quote_token(array_name));
        if(!std::isfinite(d)) fail("a value of " + quote_token(array_name) + " is not finite: " + quote_token(token));
        if(section == POINTS)
        {
          const std::string problem = coordinate_problem(d);
          if(!problem.empty()) fail(problem);
        }
        values->push_back(d);
      }
      if(values->size() != expected)
        fail("data array " + quote_token(array_name) + " has " + std::to_string(values->size()) + " values, not " +
             std::to_string(expected));
      if(section == POINT_DATA) m.point_fields.emplace_back(array_name, std::move(field));
      if(section == CELL_DATA) m.cell_fields.emplace_back(array_name, std::move(field));
      pos = closing_tag + 12;
    }
  }
  if(!vtk_file) fail_at(0, "not a VTK unstructured grid (.vtu) file");
  if(!piece_seen) fail_at(text.size(), "no <Piece>");
  if(!have_points && n_points > 0) fail_at(text.size(), "no <Points> data array");
  if(n_cells > 0 && !(have_connectivity && have_offsets && have_types))
    fail_at(text.size(), "the cells need connectivity, offsets and types arrays");
  m.points.reserve(n_points);
  for(std::size_t k = 0; k < n_points; ++k)
    m.points.push_back({coordinates[3 * k], coordinates[3 * k + 1], coordinates[3 * k + 2]});
  m.tetrahedra.reserve(n_cells);
  for(std::size_t k = 0; k < n_cells; ++k)
  {
    if(types[k] != 10 || offsets[k] != double(4 * (k + 1)))
      fail_at(text.size(), "cell " + std::to_string(k) + " is not a tetrahedron (VTK type 10, 4 points)");
    std::array<std::size_t, 4> t;
    for(int i = 0; i < 4; ++i)
    {
      const double v = connectivity[4 * k + i];
      if(!(v >= 0 && v < double(n_points)) || v != std::floor(v))
        fail_at(text.size(), "cell " + std::to_string(k) + " names a point that does not exist");
      t[i] = std::size_t(v);
    }
    m.tetrahedra.push_back(t);
  }
  return m;
}

/// \ingroup PkgEdgeSwapping3IO
/// Reads a `.vtu` file of tetrahedra; a bad file throws an error that names it and the problem.
inline Vtu_mesh read_vtu_file(const std::string& path) { return read_vtu_text(path, read_text_file(path)); }

} // namespace IO
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_IO_VTU_H
