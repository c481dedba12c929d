// SPDX-License-Identifier: GPL-3.0-or-later
// Gmsh's MSH files, versions 4.1 and 2.2, ASCII and binary, read and written
// after Gmsh's documentation ("MSH file format"). Linear tetrahedra are the
// mesh; triangles are its boundary and interface triangles. The reference of
// an element is the first physical tag of its entity (4.1) or its first tag
// (2.2), and its entity's tag when it has no physical tag; node tags are kept.
// Points, lines, quadrangles and the sections the package does not use
// ($PhysicalNames, $NodeData, $Periodic, ...) are skipped; other volume
// elements (hexahedra, prisms, pyramids, second-order tetrahedra) are refused.

#ifndef CGAL_EDGE_SWAPPING_3_IO_GMSH_H
#define CGAL_EDGE_SWAPPING_3_IO_GMSH_H

#include <CGAL/Edge_swapping_3/IO/text_input.h>
#include <CGAL/Edge_swapping_3/IO/text_output.h>
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <map>
#include <ostream>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace IO {

/// \ingroup PkgEdgeSwapping3IO
/// The content of a Gmsh MSH file that the package uses.
struct Gmsh_mesh
{
  std::vector<std::array<double, 3>> points;              ///< the nodes, in file order
  std::vector<std::size_t> point_tags;                     ///< each point's node tag
  std::vector<std::array<std::size_t, 4>> tetrahedra;      ///< 0-based point numbers
  std::vector<int> tetrahedron_references;                 ///< physical (or entity) tag of each tetrahedron
  std::vector<std::array<std::size_t, 3>> triangles;       ///< 0-based point numbers
  std::vector<int> triangle_references;                    ///< physical (or entity) tag of each triangle
};

/// \ingroup PkgEdgeSwapping3IO
/// The MSH versions and encodings written.
enum Gmsh_format { MSH_4_1_ASCII, MSH_4_1_BINARY, MSH_2_2_ASCII, MSH_2_2_BINARY };

namespace internal {

/// The number of nodes of a Gmsh element type (0 for a type not known here).
inline int gmsh_nodes_per_element(int type)
{
  static const int nodes[] = {0, 2, 3, 4, 4, 8, 6, 5, 3, 6, 9, 10, 27, 18, 14, 1, 8, 20, 15, 13,
                              9, 10, 12, 15, 15, 21, 4, 5, 6, 20, 35, 56};
  return type >= 1 && type < int(sizeof nodes / sizeof nodes[0]) ? nodes[type] : 0;
}

/// The dimension of a Gmsh element type known here.
inline int gmsh_element_dimension(int type)
{
  switch(type)
  {
  case 15: return 0;
  case 1: case 8: case 26: case 27: case 28: return 1;
  case 2: case 3: case 9: case 10: case 16: case 20: case 21: case 22: case 23: case 24: case 25: return 2;
  default: return 3;
  }
}

/// A cursor over a MSH file: ASCII tokens (counting lines) and binary values
/// (checked against the bytes left), so that every error names the place.
class Msh_cursor
{
public:
  Msh_cursor(std::string name, std::string_view text) : name_(std::move(name)), text_(text) {}

  bool binary = false;

  [[noreturn]] void fail(const std::string& what) const
  {
    if(binary_place_) throw Input_error(name_ + ": at byte " + std::to_string(pos_) + ": " + what);
    throw Input_error(name_ + ":" + std::to_string(line_) + ": " + what);
  }

  bool at_end()
  {
    skip_space();
    return pos_ == text_.size();
  }

  /// The next white-space separated token (false at the end).
  bool token(std::string_view& t)
  {
    binary_place_ = false;
    skip_space();
    if(pos_ == text_.size()) return false;
    const std::size_t begin = pos_;
    while(pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
    t = text_.substr(begin, pos_ - begin);
    return true;
  }

  std::string_view token(const char* what)
  {
    std::string_view t;
    if(!token(t)) fail(std::string("the file ends before ") + what);
    return t;
  }

  void expect(std::string_view word)
  {
    const std::string_view t = token(std::string(word).c_str());
    if(t != word) fail("expected " + std::string(word) + ", found " + quote_token(t));
  }

  /// A number of type T: a token in ASCII, raw bytes (little-endian, as
  /// checked by the file's header) in binary.
  template <class T>
  T value(const char* what)
  {
    if(binary)
    {
      binary_place_ = true;
      if(text_.size() - pos_ < sizeof(T)) fail(std::string("the file ends before ") + what);
      T v;
      std::memcpy(&v, text_.data() + pos_, sizeof(T));
      pos_ += sizeof(T);
      if constexpr(std::is_floating_point<T>::value)
        if(!std::isfinite(v)) fail(std::string(what) + " is not finite");
      return v;
    }
    const std::string_view t = token(what);
    T v{};
    const Number_status status = parse_number(t, v);
    if(status != Number_status::ok) fail(std::string("cannot read ") + what + " from " + quote_token(t));
    if constexpr(std::is_floating_point<T>::value)
      if(!std::isfinite(v)) fail(std::string(what) + " is not finite: " + quote_token(t));
    return v;
  }

  /// A count of entries of at least `min_bytes` each in what is left.
  template <class T>
  std::size_t count(const char* what, std::size_t min_bytes)
  {
    const T n = value<T>(what);
    if(n < 0) fail(std::string("negative ") + what);
    if(std::uint64_t(n) > (text_.size() - pos_ + 1) / min_bytes)
      fail(std::string(what) + " is " + std::to_string(n) + ", more than the rest of the file can hold (" +
           std::to_string(text_.size() - pos_) + " bytes)");
    return std::size_t(n);
  }

  /// Skips to just after the line that is `end` (a section's end).
  void skip_section(const std::string& end)
  {
    binary_place_ = false;
    for(;;)
    {
      const std::size_t at = text_.find(end, pos_);
      if(at == std::string_view::npos) fail("the file ends before " + end);
      line_ += std::size_t(std::count(text_.begin() + std::ptrdiff_t(pos_), text_.begin() + std::ptrdiff_t(at), '\n'));
      pos_ = at + end.size();
      if((at == 0 || text_[at - 1] == '\n') && (pos_ == text_.size() || is_space(text_[pos_]))) return;
    }
  }

  /// Moves past the end of the current line.
  void skip_line()
  {
    while(pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    if(pos_ < text_.size()) ++pos_, ++line_;
  }

  /// A count written as text on its own line (MSH 2.2 sections, binary or not).
  std::size_t ascii_count(const char* what, std::size_t min_bytes)
  {
    const bool was_binary = binary;
    binary = false;
    const std::size_t n = count<long long>(what, min_bytes);
    binary = was_binary;
    if(binary) skip_line();
    return n;
  }

private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }
  void skip_space()
  {
    while(pos_ < text_.size() && is_space(text_[pos_]))
    {
      if(text_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }

  std::string name_;
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
  bool binary_place_ = false;
};

/// Node tags to point numbers: dense when the tags are, else hashed.
class Node_numbers
{
public:
  void reserve(std::size_t nodes, std::size_t max_tag)
  {
    dense_ = max_tag <= 4 * nodes + 1024;
    if(dense_) by_tag_.assign(max_tag + 1, none);
  }
  bool add(std::size_t tag, std::size_t number)
  {
    if(dense_ && tag < by_tag_.size())
    {
      if(by_tag_[tag] != none) return false;
      by_tag_[tag] = number;
      return true;
    }
    return hashed_.emplace(tag, number).second;
  }
  std::size_t find(std::size_t tag) const
  {
    if(dense_ && tag < by_tag_.size()) return by_tag_[tag];
    const auto it = hashed_.find(tag);
    return it == hashed_.end() ? none : it->second;
  }
  static constexpr std::size_t none = std::size_t(-1);

private:
  bool dense_ = false;
  std::vector<std::size_t> by_tag_;
  std::unordered_map<std::size_t, std::size_t> hashed_;
};

/// Elements as read, before the nodes are known to be those of tetrahedra.
struct Msh_elements
{
  std::vector<std::array<std::size_t, 4>> tetrahedra; // node tags
  std::vector<int> tetrahedron_references;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<int> triangle_references;
};

/// Takes one element of `type` with node tags `nodes` and reference `reference`.
inline void add_element(Msh_cursor& in, Msh_elements& e, int type, const std::size_t* nodes, int reference)
{
  if(type == 4)
  {
    e.tetrahedra.push_back({nodes[0], nodes[1], nodes[2], nodes[3]});
    e.tetrahedron_references.push_back(reference);
  }
  else if(type == 2)
  {
    e.triangles.push_back({nodes[0], nodes[1], nodes[2]});
    e.triangle_references.push_back(reference);
  }
  else if(gmsh_element_dimension(type) == 3)
    in.fail("element type " + std::to_string(type) +
            " is a volume element other than a linear tetrahedron (hexahedron, prism, pyramid or second order): "
            "only linear tetrahedra are supported (Gmsh: mesh with tetrahedra, element order 1)");
}

inline int reference_of(Msh_cursor& in, long long tag)
{
  if(tag < -2147483647 || tag > 2147483647) in.fail("the tag " + std::to_string(tag) + " is out of range");
  return int(tag);
}

} // namespace internal

/// \ingroup PkgEdgeSwapping3IO
/// Reads the Gmsh MSH file whose content is `text` (`name` for messages):
/// version 4.1 or 2.2, ASCII or binary. Keeps the nodes (with their tags)
/// in file order, the linear tetrahedra and the triangles.
/// Throws `Input_error` naming the file, the line (or byte) and the problem.
inline Gmsh_mesh read_gmsh_text(const std::string& name, std::string_view text)
{
  using namespace internal;
  Msh_cursor in(name, text);
  std::string_view t;
  if(!in.token(t)) in.fail("empty file");
  if(t != "$MeshFormat") in.fail("not a Gmsh MSH file: it does not start with $MeshFormat");
  const std::string_view version = in.token("the version");
  const bool v4 = version == "4.1";
  if(!v4 && version != "2.2")
    in.fail("MSH version " + std::string(quote_token(version)) +
            " is not supported: write version 4.1 or 2.2 (Gmsh: -format msh41 or msh22)");
  const int file_type = in.value<int>("the file type");
  const int data_size = in.value<int>("the data size");
  if(file_type != 0 && file_type != 1) in.fail("the file type is " + std::to_string(file_type) + ", not 0 or 1");
  if(data_size != 8) in.fail("the data size is " + std::to_string(data_size) + ", not 8");
  if(file_type == 1)
  {
    // The integer 1 in binary on the next line tells the byte order.
    in.skip_line();
    in.binary = true;
    if(in.value<int>("the binary header's integer") != 1)
      in.fail("the binary header's integer is not 1: the file was written with another byte order");
  }
  in.expect("$EndMeshFormat");

  // (dimension, entity tag) -> its first physical tag, when it has one (4.1).
  std::map<std::pair<int, int>, int> physical;
  Gmsh_mesh m;
  Msh_elements e;
  Node_numbers numbers;
  std::vector<std::array<double, 3>> coordinates;
  std::vector<std::size_t> tags;
  bool nodes_seen = false, elements_seen = false;
  while(in.token(t))
  {
    if(in.binary && t.size() > 1 && t[0] == '$') in.skip_line(); // binary data starts on the next line
    if(t == "$Entities" && v4)
    {
      std::size_t n[4];
      for(int d = 0; d < 4; ++d) n[d] = in.count<std::uint64_t>("the number of entities", in.binary ? 4 : 2);
      for(int d = 0; d < 4; ++d)
        for(std::size_t k = 0; k < n[d]; ++k)
        {
          const int tag = in.value<int>("an entity tag");
          for(int c = 0; c < (d == 0 ? 3 : 6); ++c) in.value<double>("an entity's bounding box");
          const std::size_t p = in.count<std::uint64_t>("the number of physical tags", in.binary ? 4 : 2);
          for(std::size_t j = 0; j < p; ++j)
          {
            const int ph = in.value<int>("a physical tag");
            if(j == 0) physical[{d, tag}] = ph;
          }
          if(d > 0)
          {
            const std::size_t b = in.count<std::uint64_t>("the number of bounding entities", in.binary ? 4 : 2);
            for(std::size_t j = 0; j < b; ++j) in.value<int>("a bounding entity tag");
          }
        }
      in.expect("$EndEntities");
    }
    else if(t == "$Nodes")
    {
      if(nodes_seen) in.fail("a second $Nodes section");
      nodes_seen = true;
      if(v4)
      {
        const std::size_t blocks = in.count<std::uint64_t>("the number of node blocks", in.binary ? 20 : 8);
        const std::size_t total = in.count<std::uint64_t>("the number of nodes", in.binary ? 32 : 8);
        in.value<std::uint64_t>("the smallest node tag");
        const std::uint64_t max_tag = in.value<std::uint64_t>("the largest node tag");
        coordinates.reserve(total);
        tags.reserve(total);
        numbers.reserve(total, std::size_t(std::min<std::uint64_t>(max_tag, std::uint64_t(1) << 40)));
        for(std::size_t b = 0; b < blocks; ++b)
        {
          const int dim = in.value<int>("an entity dimension");
          in.value<int>("an entity tag");
          const int parametric = in.value<int>("the parametric flag");
          const std::size_t n = in.count<std::uint64_t>("the number of nodes in a block", in.binary ? 32 : 8);
          if(coordinates.size() + n > total) in.fail("the node blocks hold more nodes than the section's count");
          if(dim < 0 || dim > 3 || (parametric != 0 && parametric != 1))
            in.fail("bad node block header (dimension " + std::to_string(dim) + ", parametric " +
                    std::to_string(parametric) + ")");
          const std::size_t first = tags.size();
          for(std::size_t k = 0; k < n; ++k) tags.push_back(in.value<std::uint64_t>("a node tag"));
          for(std::size_t k = 0; k < n; ++k)
          {
            std::array<double, 3> p;
            for(int c = 0; c < 3; ++c) p[c] = in.value<double>("a coordinate");
            for(int c = 0; c < parametric * dim; ++c) in.value<double>("a parametric coordinate");
            coordinates.push_back(p);
            if(!numbers.add(tags[first + k], first + k)) in.fail("node tag " + std::to_string(tags[first + k]) + " is repeated");
          }
        }
        if(coordinates.size() != total)
          in.fail("the node blocks hold " + std::to_string(coordinates.size()) + " nodes, not " + std::to_string(total));
      }
      else
      {
        const std::size_t n = in.ascii_count("the number of nodes", in.binary ? 28 : 8);
        coordinates.reserve(n);
        tags.reserve(n);
        numbers.reserve(n, 4 * n);
        for(std::size_t k = 0; k < n; ++k)
        {
          const long long tag = in.binary ? in.value<int>("a node tag") : in.value<long long>("a node tag");
          if(tag < 0) in.fail("negative node tag");
          std::array<double, 3> p;
          for(int c = 0; c < 3; ++c) p[c] = in.value<double>("a coordinate");
          tags.push_back(std::size_t(tag));
          coordinates.push_back(p);
          if(!numbers.add(std::size_t(tag), k)) in.fail("node tag " + std::to_string(tag) + " is repeated");
        }
      }
      in.expect("$EndNodes");
    }
    else if(t == "$Elements")
    {
      if(elements_seen) in.fail("a second $Elements section");
      elements_seen = true;
      std::vector<std::size_t> nodes;
      if(v4)
      {
        const std::size_t blocks = in.count<std::uint64_t>("the number of element blocks", in.binary ? 20 : 8);
        const std::size_t total = in.count<std::uint64_t>("the number of elements", in.binary ? 16 : 4);
        in.value<std::uint64_t>("the smallest element tag");
        in.value<std::uint64_t>("the largest element tag");
        std::size_t read = 0;
        for(std::size_t b = 0; b < blocks; ++b)
        {
          const int dim = in.value<int>("an entity dimension");
          const int entity = in.value<int>("an entity tag");
          const int type = in.value<int>("an element type");
          const std::size_t n = in.count<std::uint64_t>("the number of elements in a block", in.binary ? 16 : 4);
          const int per = gmsh_nodes_per_element(type);
          if(per == 0) in.fail("element type " + std::to_string(type) + " is not known");
          if(dim < 0 || dim > 3) in.fail("entity dimension " + std::to_string(dim));
          read += n;
          if(read > total) in.fail("the element blocks hold more elements than the section's count");
          const auto it = physical.find({dim, entity});
          const int reference = it == physical.end() ? entity : it->second;
          nodes.resize(std::size_t(per));
          for(std::size_t k = 0; k < n; ++k)
          {
            in.value<std::uint64_t>("an element tag");
            for(int j = 0; j < per; ++j) nodes[std::size_t(j)] = in.value<std::uint64_t>("a node tag");
            add_element(in, e, type, nodes.data(), reference);
          }
        }
        if(read != total) in.fail("the element blocks hold " + std::to_string(read) + " elements, not " + std::to_string(total));
      }
      else
      {
        const std::size_t total = in.ascii_count("the number of elements", in.binary ? 12 : 6);
        std::size_t read = 0;
        while(read < total)
        {
          int type, n = 1, ntags;
          if(in.binary)
          {
            type = in.value<int>("an element type");
            n = in.value<int>("the number of elements in a block");
            ntags = in.value<int>("the number of tags");
            if(n <= 0 || std::size_t(n) > total - read) in.fail("bad element block size " + std::to_string(n));
          }
          for(int k = 0; k < n; ++k)
          {
            in.value<int>("an element number");
            if(!in.binary)
            {
              type = in.value<int>("an element type");
              ntags = in.value<int>("the number of tags");
            }
            if(ntags < 0 || ntags > 1000) in.fail("the number of tags is " + std::to_string(ntags));
            long long first_tags[2] = {0, 0};
            for(int j = 0; j < ntags; ++j)
            {
              const int tag = in.value<int>("a tag");
              if(j < 2) first_tags[j] = tag;
            }
            const int per = gmsh_nodes_per_element(type);
            if(per == 0) in.fail("element type " + std::to_string(type) + " is not known");
            nodes.resize(std::size_t(per));
            for(int j = 0; j < per; ++j)
            {
              const int tag = in.value<int>("a node number");
              if(tag < 0) in.fail("negative node number");
              nodes[std::size_t(j)] = std::size_t(tag);
            }
            // The physical tag, or the elementary one where there is none (0).
            add_element(in, e, type, nodes.data(), reference_of(in, first_tags[0] != 0 ? first_tags[0] : first_tags[1]));
          }
          read += std::size_t(n);
        }
      }
      in.expect("$EndElements");
    }
    else if(t == "$PartitionedEntities")
      in.fail("a partitioned mesh: write it unpartitioned (Gmsh: Mesh.PartitionSplitMeshFiles, or no partitioning)");
    else if(t.size() > 1 && t[0] == '$')
      in.skip_section("$End" + std::string(t.substr(1))); // a section not used here
    else
      in.fail("expected a section ($Nodes, $Elements, ...), found " + quote_token(t));
  }
  if(!nodes_seen) in.fail("no $Nodes section");
  if(!elements_seen) in.fail("no $Elements section");

  auto node = [&](std::size_t tag) {
    const std::size_t k = numbers.find(tag);
    if(k == Node_numbers::none) in.fail("an element names node " + std::to_string(tag) + ", which is not in $Nodes");
    return k;
  };
  m.points = std::move(coordinates);
  m.point_tags = std::move(tags);
  m.tetrahedra.reserve(e.tetrahedra.size());
  for(const auto& tet : e.tetrahedra) m.tetrahedra.push_back({node(tet[0]), node(tet[1]), node(tet[2]), node(tet[3])});
  m.tetrahedron_references = std::move(e.tetrahedron_references);
  m.triangles.reserve(e.triangles.size());
  for(const auto& tri : e.triangles) m.triangles.push_back({node(tri[0]), node(tri[1]), node(tri[2])});
  m.triangle_references = std::move(e.triangle_references);
  return m;
}

namespace internal {

/// Writes numbers as MSH text or as raw bytes, through a `Text_sink`.
class Msh_writer
{
public:
  Msh_writer(Text_sink& out, bool binary) : out_(out), binary_(binary) {}
  template <class T>
  Msh_writer& operator<<(T v)
  {
    if(binary_) out_ << std::string_view(reinterpret_cast<const char*>(&v), sizeof v);
    else
    {
      if(!first_) out_ << ' ';
      out_ << v;
    }
    first_ = false;
    return *this;
  }
  /// The end of a line of numbers (in binary: nothing).
  void end_line()
  {
    if(!binary_) out_ << '\n';
    first_ = true;
  }
  /// A line of text (a section's header or end, a count of MSH 2.2).
  void text(std::string_view line)
  {
    if(binary_ && !first_) out_ << '\n';
    out_ << line << '\n';
    first_ = true;
  }

private:
  Text_sink& out_;
  bool binary_;
  bool first_ = true;
};

} // namespace internal

/// \ingroup PkgEdgeSwapping3IO
/// Writes `m` as a Gmsh MSH file in `format`: each tetrahedron reference is
/// a volume entity with that physical tag, each triangle reference a surface
/// entity likewise; node tags are `m.point_tags` (1, 2, ... where empty).
/// Throws `std::domain_error` for a coordinate that is not finite.
inline void write_gmsh_file(std::ostream& out, const Gmsh_mesh& m, Gmsh_format format = MSH_4_1_ASCII)
{
  using internal::Msh_writer;
  const bool binary = format == MSH_4_1_BINARY || format == MSH_2_2_BINARY;
  const bool v4 = format == MSH_4_1_ASCII || format == MSH_4_1_BINARY;
  for(const auto& p : m.points)
    for(double x : p) finite_value(x, "a coordinate");
  auto tag_of = [&](std::size_t k) { return m.point_tags.empty() ? k + 1 : m.point_tags[k]; };
  std::map<int, std::vector<std::size_t>> volumes, surfaces; // reference -> its elements
  for(std::size_t k = 0; k < m.tetrahedra.size(); ++k)
    volumes[m.tetrahedron_references.empty() ? 1 : m.tetrahedron_references[k]].push_back(k);
  for(std::size_t k = 0; k < m.triangles.size(); ++k) surfaces[m.triangle_references[k]].push_back(k);
  // Triangles in the order of their sorted points: the file does not depend on the order of the cells.
  auto sorted = [&](std::size_t k) {
    auto t = m.triangles[k];
    std::sort(t.begin(), t.end());
    return t;
  };
  for(auto& [r, tris] : surfaces)
    std::sort(tris.begin(), tris.end(), [&](std::size_t a, std::size_t b) { return sorted(a) < sorted(b); });
  Text_sink sink(out);
  Msh_writer w(sink, binary);
  w.text("$MeshFormat");
  w.text(v4 ? (binary ? "4.1 1 8" : "4.1 0 8") : (binary ? "2.2 1 8" : "2.2 0 8"));
  if(binary) w << 1; // the byte order
  w.text("$EndMeshFormat");
  std::size_t max_tag = 0;
  for(std::size_t k = 0; k < m.points.size(); ++k) max_tag = (std::max)(max_tag, tag_of(k));
  const std::size_t elements = m.tetrahedra.size() + m.triangles.size();
  if(v4)
  {
    // Entity tags must be positive: a reference r is entity `e` with physical tag r.
    std::map<int, int> volume_entity, surface_entity;
    for(const auto& [r, cells] : volumes) volume_entity.emplace(r, int(volume_entity.size()) + 1);
    for(const auto& [r, tris] : surfaces) surface_entity.emplace(r, int(surface_entity.size()) + 1);
    w.text("$Entities");
    w << std::uint64_t(0) << std::uint64_t(0) << std::uint64_t(surfaces.size()) << std::uint64_t(volumes.size());
    w.end_line();
    for(const auto* entities : {&surface_entity, &volume_entity})
      for(const auto& [r, entity] : *entities)
      {
        w << entity;
        for(int c = 0; c < 6; ++c) w << 0.0;
        w << std::uint64_t(1) << r << std::uint64_t(0);
        w.end_line();
      }
    w.text("$EndEntities");
    w.text("$Nodes");
    w << std::uint64_t(1) << std::uint64_t(m.points.size()) << std::uint64_t(m.points.empty() ? 0 : 1)
      << std::uint64_t(max_tag);
    w.end_line();
    w << 3 << (volumes.empty() ? 1 : volume_entity.begin()->second) << 0 << std::uint64_t(m.points.size());
    w.end_line();
    for(std::size_t k = 0; k < m.points.size(); ++k)
    {
      w << std::uint64_t(tag_of(k));
      w.end_line();
    }
    for(const auto& p : m.points)
    {
      w << p[0] << p[1] << p[2];
      w.end_line();
    }
    w.text("$EndNodes");
    w.text("$Elements");
    w << std::uint64_t(volumes.size() + surfaces.size()) << std::uint64_t(elements) << std::uint64_t(elements ? 1 : 0)
      << std::uint64_t(elements);
    w.end_line();
    std::uint64_t number = 0;
    for(const auto& [r, tris] : surfaces)
    {
      w << 2 << surface_entity[r] << 2 << std::uint64_t(tris.size());
      w.end_line();
      for(auto k : tris)
      {
        w << ++number << std::uint64_t(tag_of(m.triangles[k][0])) << std::uint64_t(tag_of(m.triangles[k][1]))
          << std::uint64_t(tag_of(m.triangles[k][2]));
        w.end_line();
      }
    }
    for(const auto& [r, cells] : volumes)
    {
      w << 3 << volume_entity[r] << 4 << std::uint64_t(cells.size());
      w.end_line();
      for(auto k : cells)
      {
        w << ++number;
        for(auto v : m.tetrahedra[k]) w << std::uint64_t(tag_of(v));
        w.end_line();
      }
    }
    w.text("$EndElements");
    return;
  }
  // Version 2.2: 32-bit numbers; the physical tag and the elementary one (the same) on each element.
  if(max_tag > 2147483647 || elements > 2147483647)
    throw std::invalid_argument("too many nodes or elements for MSH 2.2 (tags above 2^31): write MSH 4.1");
  w.text("$Nodes");
  w.text(std::to_string(m.points.size()));
  for(std::size_t k = 0; k < m.points.size(); ++k)
  {
    w << int(tag_of(k)) << m.points[k][0] << m.points[k][1] << m.points[k][2];
    w.end_line();
  }
  w.text("$EndNodes");
  w.text("$Elements");
  w.text(std::to_string(elements));
  int number = 0;
  auto block = [&](int type, std::size_t n) {
    if(binary) w << type << int(n) << 2;
  };
  for(const auto& [r, tris] : surfaces)
  {
    block(2, tris.size());
    for(auto k : tris)
    {
      w << ++number;
      if(!binary) w << 2;
      if(!binary) w << 2;
      w << r << r << int(tag_of(m.triangles[k][0])) << int(tag_of(m.triangles[k][1])) << int(tag_of(m.triangles[k][2]));
      w.end_line();
    }
  }
  for(const auto& [r, cells] : volumes)
  {
    block(4, cells.size());
    for(auto k : cells)
    {
      w << ++number;
      if(!binary) w << 4 << 2;
      w << r << r;
      for(auto v : m.tetrahedra[k]) w << int(tag_of(v));
      w.end_line();
    }
  }
  w.text("$EndElements");
}

} // namespace IO
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_IO_GMSH_H
