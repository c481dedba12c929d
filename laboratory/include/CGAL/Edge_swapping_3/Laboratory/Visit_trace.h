// SPDX-License-Identifier: GPL-3.0-or-later
// Traces of the laboratory: every visit of a run (facet, configuration, tags
// read and set, decision, flip) and the whole state (cells and tags) at every
// round's end, as JSON lines with the points numbered as in the case. An
// independent program replays a trace from its start and checks each line
// (laboratory/checker/trace_checker.h); the format is in
// laboratory/doc/traces.md.

#ifndef CGAL_EDGE_SWAPPING_3_LABORATORY_VISIT_TRACE_H
#define CGAL_EDGE_SWAPPING_3_LABORATORY_VISIT_TRACE_H

#include <CGAL/Kernel_traits.h>
#include <CGAL/Edge_swapping_3/Flip_plan.h>
#include <CGAL/Edge_swapping_3/Visit_record.h>
#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <nlohmann/json.hpp>
#include <algorithm>
#include <array>
#include <map>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {

/// \ingroup PkgEdgeSwapping3Laboratory
/// A visit visitor (`visit_visitor`) that writes a trace to a stream, the
/// points numbered by their place in `points`.
template <class Point>
class Visit_trace_writer
{
public:
  /// \pre the points are distinct
  Visit_trace_writer(std::ostream& out, const std::vector<Point>& points) : out_(out)
  {
    for(std::size_t k = 0; k < points.size(); ++k) number_.emplace(points[k], k);
  }

  /// Writes the first line: `header` (what the run is) with the points and the start cells.
  template <class Tr>
  void start(const Tr& tr, nlohmann::json header)
  {
    header["format"] = "Edge_swapping_3 visit trace";
    header["version"] = 1;
    // Random sweeps (same-cycle) take their seeds as internal::random_sweep_seed
    // does; traces without this field are older (traces.md).
    const std::string reading = header.value("reading", "");
    const std::string same_cycle = ",same-cycle";
    if(header.value("order", "") == "random" && reading.size() > same_cycle.size() &&
       reading.compare(reading.size() - same_cycle.size(), same_cycle.size(), same_cycle) == 0)
      header["sweep_seeds"] = "m(m(seed) + cycle)";
    nlohmann::json points = nlohmann::json::array();
    std::vector<const Point*> by_number(number_.size());
    for(const auto& [p, k] : number_) by_number[k] = &p;
    for(const Point* p : by_number)
      points.push_back({CGAL::to_double(p->x()), CGAL::to_double(p->y()), CGAL::to_double(p->z())});
    header["points"] = points;
    header["cells"] = cells_of(tr);
    out_ << header.dump() << '\n';
  }

  // The visit and round lines are written by hand, as nlohmann::json's dump()
  // writes them (keys in sorted order, no spaces), for speed: a trace has a line
  // per visit, and the laboratory writes millions. The names have no characters
  // to escape.

  /// One line per visit.
  template <class Tr>
  void visit(const Tr&, const Visit_record<Tr>& r)
  {
    line_.clear();
    line_ += "{\"apexes\":[";
    append_numbers(r.apexes);
    line_ += "],\"cells\":";
    append_cells(r.cells);
    line_ += ",\"created\":";
    append_cells(r.created);
    line_ += r.locally_delaunay ? ",\"delaunay\":true,\"facet\":[" : ",\"delaunay\":false,\"facet\":[";
    append_numbers(r.facet);
    line_ += "],\"flip\":";
    if(r.flip < 0)
      line_ += "null";
    else
      append_name(flip_kind_name(Flip_kind(r.flip)));
    line_ += ",\"kind\":";
    append_name(configuration_kind_name(r.kind));
    line_ += ",\"new_tags\":";
    append_cells(r.new_tags);
    if(r.scanned) line_ += ",\"scan\":true";
    line_ += ",\"tagged\":[";
    for(std::size_t k = 0; k < r.tagged_before.size(); ++k)
      line_ += k == 0 ? (r.tagged_before[k] ? "1" : "0") : (r.tagged_before[k] ? ",1" : ",0");
    line_ += "]}\n";
    out_ << line_;
  }

  /// One line per round: its number, its swaps, and the state at its end.
  template <class Tr, class IsTagged>
  void end_of_round(const Tr& tr, const Cycle_record& record, const IsTagged& is_tagged)
  {
    std::vector<std::array<std::size_t, 4>> tagged;
    for(auto c : tr.finite_cell_handles())
      if(is_tagged(c)) tagged.push_back(sorted_numbers(c));
    std::sort(tagged.begin(), tagged.end());
    line_.clear();
    line_ += "{\"cells\":";
    append_sorted_cells(cells_of(tr));
    line_ += ",\"new_tags\":" + std::to_string(record.new_tags);
    line_ += ",\"round\":" + std::to_string(record.cycle);
    line_ += ",\"swaps\":" + std::to_string(record.total_swaps());
    line_ += ",\"tagged\":";
    append_sorted_cells(tagged);
    line_ += "}\n";
    out_ << line_;
  }

  /// The last line: how the run ended.
  void finish(const char* ending, std::size_t rounds)
  {
    out_ << nlohmann::json{{"end", ending}, {"rounds", rounds}}.dump() << '\n';
  }

private:
  struct Less_xyz
  {
    bool operator()(const Point& a, const Point& b) const
    {
      return typename CGAL::Kernel_traits<Point>::Kernel().compare_xyz_3_object()(a, b) == SMALLER;
    }
  };

  template <class Vertex_handle>
  std::size_t number(Vertex_handle v) const
  {
    const auto it = number_.find(internal::bare_point(v->point()));
    if(it == number_.end()) throw std::invalid_argument("a trace's triangulation has a point not in its case");
    return it->second;
  }

  template <class Cell_handle>
  std::array<std::size_t, 4> sorted_numbers(Cell_handle c) const
  {
    std::array<std::size_t, 4> t{number(c->vertex(0)), number(c->vertex(1)), number(c->vertex(2)), number(c->vertex(3))};
    std::sort(t.begin(), t.end());
    return t;
  }

  /// The vertices' numbers, comma-separated.
  template <class Vertices>
  void append_numbers(const Vertices& vertices)
  {
    for(std::size_t k = 0; k < vertices.size(); ++k)
    {
      if(k > 0) line_ += ',';
      line_ += std::to_string(number(vertices[k]));
    }
  }

  /// A list of cells, each the numbers of its vertices in the cell's order.
  template <class Cells>
  void append_cells(const Cells& cells)
  {
    line_ += '[';
    for(std::size_t k = 0; k < cells.size(); ++k)
    {
      line_ += k == 0 ? "[" : ",[";
      append_numbers(cells[k]);
      line_ += ']';
    }
    line_ += ']';
  }

  /// A list of cells given by their numbers.
  void append_sorted_cells(const std::vector<std::array<std::size_t, 4>>& cells)
  {
    line_ += '[';
    for(std::size_t k = 0; k < cells.size(); ++k)
    {
      const auto& t = cells[k];
      line_ += k == 0 ? "[" : ",[";
      line_ += std::to_string(t[0]) + ',' + std::to_string(t[1]) + ',' + std::to_string(t[2]) + ',' +
               std::to_string(t[3]) + ']';
    }
    line_ += ']';
  }

  void append_name(const char* name)
  {
    line_ += '"';
    line_ += name;
    line_ += '"';
  }

  /// The finite cells, each as its sorted point numbers, in sorted order: the state's canonical form.
  template <class Tr>
  std::vector<std::array<std::size_t, 4>> cells_of(const Tr& tr) const
  {
    std::vector<std::array<std::size_t, 4>> cells;
    for(auto c : tr.finite_cell_handles()) cells.push_back(sorted_numbers(c));
    std::sort(cells.begin(), cells.end());
    return cells;
  }

  std::ostream& out_;
  std::map<Point, std::size_t, Less_xyz> number_;
  std::string line_; // the line being written, its memory kept from line to line
};

} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_LABORATORY_VISIT_TRACE_H
