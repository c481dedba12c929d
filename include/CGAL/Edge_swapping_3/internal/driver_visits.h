// SPDX-License-Identifier: GPL-3.0-or-later
// The visits and rounds of a swap driver, traced when a visit visitor
// watches them (the laboratory's traces).

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_DRIVER_VISITS_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_DRIVER_VISITS_H

#include <CGAL/Edge_swapping_3/Visit_record.h>
#include <CGAL/Edge_swapping_3/internal/driver_slot_state.h>
#include <algorithm>
#include <array>
#include <set>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// The visits and rounds of a swap driver: a visit asks the rule (with the
/// driver, `Derived`) what to do at a facet, and with a visit visitor each
/// visit and round is traced (the laboratory's traces, Visit_record.h).
template <class Derived, class Base, class VisitVisitor>
class Driver_visits : public Base
{
protected:
  CGAL_EDGE_SWAPPING_3_DRIVER_STATE_NAMES

  static constexpr bool tracing = !std::is_same<std::decay_t<decltype(unwrap(std::declval<VisitVisitor&>()))>,
                                                No_visit_visitor>::value;

  Driver_visits(Tr& tr, const Driver_settings& settings) : Base(tr, settings) {}

  template <class Rule>
  void visit_facet(Rule& visit, Cell_handle c, int i)
  {
    ++record_.visits;
    if constexpr(tracing)
    {
      Visit_record<Tr> record;
      before_visit(record, c, i);
      trace_ = &record;
      visit(static_cast<Derived&>(*this), c, i);
      trace_ = nullptr;
      unwrap(*visit_visitor_).visit(tr_, record);
    }
    else
      visit(static_cast<Derived&>(*this), c, i);
  }

  /// What a trace says of facet (c, i) before its visit.
  void before_visit(Visit_record<Tr>& record, Cell_handle c, int i) const
  {
    const Cell_handle n = c->neighbor(i);
    for(int k = 0; k < 3; ++k) record.facet[k] = c->vertex((i + 1 + k) & 3);
    record.apexes = {c->vertex(i), n->vertex(n->index(c))};
    if constexpr(!Is_weighted_point<typename Tr::Point>::value)
      record.locally_delaunay = is_locally_delaunay(tr_, c, i, settings_.perturbation);
    const Configuration conf = classify_facet(tr_, c, i);
    record.kind = conf.kind();
    record.cells.push_back(cell_vertices(c));
    record.tagged_before.push_back(is_tagged(c));
    record.cells.push_back(cell_vertices(n));
    record.tagged_before.push_back(is_tagged(n));
    for(int k = 1; k < conf.number_of_tetrahedra(); ++k)
      if(conf.tetrahedron(k) != n)
      {
        record.cells.push_back(cell_vertices(conf.tetrahedron(k)));
        record.tagged_before.push_back(is_tagged(conf.tetrahedron(k)));
      }
  }

  void end_round(Swap_report& report)
  {
    record_.rule = round_rule_;
    record_.cells = number_of_finite_cells();
    if(settings_.record_non_delaunay_facets)
      record_.non_delaunay_facets = (long long)number_of_non_delaunay_facets(tr_, settings_.perturbation);
    report.cycles.push_back(record_);
    if(settings_.cycle_visitor) settings_.cycle_visitor(record_);
    if constexpr(tracing)
      unwrap(*visit_visitor_).end_of_round(tr_, record_, [this](Cell_handle c) { return is_tagged(c); });
  }

  // ---- what a trace records ----

  void trace_new_tag(Cell_handle c)
  {
    if constexpr(tracing)
      if(trace_ != nullptr) trace_->new_tags.push_back(cell_vertices(c));
  }

  void trace_flip(const Flip_plan<Tr>& plan, const std::array<Cell_handle, 4>& created, int n)
  {
    if constexpr(tracing)
      if(trace_ != nullptr)
      {
        trace_->flip = int(plan.kind);
        for(int k = 0; k < n; ++k) // a 2-2 flip also makes cells outside the hull
          if(!tr_.is_infinite(created[k])) trace_->created.push_back(cell_vertices(created[k]));
      }
  }

  /// A scan before the work queue found `facets` to visit: the trace lists
  /// its visits of the others.
  void trace_scanned_visits(const std::vector<std::pair<Cell_handle, int>>& facets)
  {
    if constexpr(tracing)
    {
      // The trace lists the scan's visits of the facets it found locally Delaunay.
      std::set<std::array<Vertex_handle, 3>> failing;
      auto key = [](Cell_handle c, int i) {
        std::array<Vertex_handle, 3> k{c->vertex((i + 1) & 3), c->vertex((i + 2) & 3), c->vertex((i + 3) & 3)};
        std::sort(k.begin(), k.end());
        return k;
      };
      for(const auto& [c, i] : facets) failing.insert(key(c, i));
      for(Cell_handle c : tr_.finite_cell_handles())
        for(int i = 0; i < 4; ++i)
          if(!tr_.is_infinite(c->neighbor(i)) && holds_facet(tr_, c, i) && !failing.count(key(c, i)))
          {
            Visit_record<Tr> record;
            before_visit(record, c, i);
            record.scanned = true;
            unwrap(*visit_visitor_).visit(tr_, record);
          }
    }
  }

  VisitVisitor* visit_visitor_ = nullptr;
  Visit_record<Tr>* trace_ = nullptr; // the record of the visit under way (tracing only)
};

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

// The names of Driver_visits in a layer derived from it (`Base`).
#define CGAL_EDGE_SWAPPING_3_DRIVER_VISITS_NAMES \
  using Base::tracing; \
  using Base::visit_facet; \
  using Base::end_round; \
  using Base::visit_visitor_;

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_DRIVER_VISITS_H
