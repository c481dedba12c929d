// SPDX-License-Identifier: GPL-3.0-or-later
// What a swap driver is told (Driver_settings) and what it asks of a rule
// and of its visitors at compile time, with the small keys and hashes its
// tables use.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_DRIVER_SETTINGS_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_DRIVER_SETTINGS_H

#include <CGAL/Random.h>
#include <CGAL/Edge_swapping_3/Delaunay_criterion.h>
#include <CGAL/Edge_swapping_3/Helper_reading.h>
#include <CGAL/Edge_swapping_3/Swap_report.h>
#include <CGAL/Edge_swapping_3/internal/bare_point.h>
#include <CGAL/Edge_swapping_3/internal/facet_key.h>
#include <CGAL/Edge_swapping_3/internal/flat_hash_map.h>
#include <array>
#include <cstdint>
#include <cstring>
#include <functional>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

struct Driver_settings
{
  Schedule schedule = WORK_QUEUE;
  Face_order face_order = STORAGE_ORDER;
  unsigned int random_seed = 0;
  std::size_t max_rounds = 1000;
  bool record_non_delaunay_facets = false;
  Perturbation perturbation = CGAL_PERTURBATION;
  std::function<void(const Cycle_record&)> cycle_visitor;
  Helper_reading reading; // the helper's, on the paper's cycles
  // Under the fixed face order on the paper's cycles, a state that comes back
  // ends the work: its period is added up to the limit, not run (see
  // `skip_repeated_cycles`). Only for a rule that reads nothing but the cells
  // and the tags (`Rule::reads_only_cells_and_tags`), and with no flip or
  // visit visitor, which would miss the flips not run.
  bool skip_repeated_cycles = true;
  std::size_t* cycles_skipped = nullptr; // if given, the cycles added up instead of run
};

/// Whether a rule declares that its decisions read only the cells and the
/// driver's tags (then a state that comes back repeats the run).
template <class Rule, class = void>
struct Reads_only_cells_and_tags : std::false_type {};
template <class Rule>
struct Reads_only_cells_and_tags<Rule, std::void_t<decltype(Rule::reads_only_cells_and_tags)>>
  : std::bool_constant<Rule::reads_only_cells_and_tags> {};

/// The rule a driver applies, for its rounds' records: `Rule::round_rule`,
/// else the plain rule (Algorithm 2 under a criterion).
template <class Rule, class = void>
struct Round_rule_of : std::integral_constant<Round_rule, PLAIN_RULE> {};
template <class Rule>
struct Round_rule_of<Rule, std::void_t<decltype(Rule::round_rule)>>
  : std::integral_constant<Round_rule, Rule::round_rule> {};

/// A visitor given by value or through `std::ref`.
template <class T>
T& unwrap(T& t) { return t; }
template <class T>
T& unwrap(std::reference_wrapper<T> r) { return r.get(); }

/// A uniform random permutation (Fisher-Yates) drawn from `rng`.
template <class Vector>
void shuffle_uniformly(Vector& items, CGAL::Random& rng)
{
  for(std::size_t k = items.size(); k > 1; --k)
    std::swap(items[k - 1], items[std::size_t(rng.get_int(0, int(k)))]);
}

/// Of the two finite cells of an interior facet, the one whose opposite vertex
/// is lexicographically smaller holds it: the choice never depends on addresses.
template <class Tr>
bool holds_facet(const Tr& tr, typename Tr::Cell_handle c, int i)
{
  const auto n = c->neighbor(i);
  if(tr.is_infinite(c) || tr.is_infinite(n)) return false;
  const auto m = n->vertex(n->index(c));
  return tr.geom_traits().compare_xyz_3_object()(internal::bare_point(c->vertex(i)->point()), internal::bare_point(m->point())) == SMALLER;
}

/// Whether `rule` may see each facet from either of its cells in round 1. A
/// rule whose `sees_facet_from_either_side()` is true has one outcome whatever
/// the visit order (the perturbed Delaunay triangulation is unique): its facets
/// are then visited from the cell with the smaller address, a test that reads
/// no other cell. Other rules keep `holds_facet`, so that their result does not
/// depend on addresses.
template <class Rule, class = void>
struct Has_either_side_test : std::false_type {};
template <class Rule>
struct Has_either_side_test<Rule, std::void_t<decltype(std::declval<const Rule&>().sees_facet_from_either_side())>>
  : std::true_type {};

template <class Rule>
bool sees_facet_from_either_side(const Rule& rule)
{
  if constexpr(Has_either_side_test<Rule>::value) return rule.sees_facet_from_either_side();
  else return false;
}

/// A hash of an edge by the coordinates of its two points, in either order.
struct Edge_point_hash
{
  template <class Point>
  static std::uint64_t bits_of(const Point& p)
  {
    std::uint64_t h = 0;
    for(const double x : {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())})
    {
      std::uint64_t b;
      std::memcpy(&b, &x, sizeof b);
      h = mix_bits(h ^ b);
    }
    return h;
  }
  template <class Key>
  std::size_t operator()(const Key& e) const
  {
    return std::size_t(bits_of(internal::bare_point(e.a->point())) + bits_of(internal::bare_point(e.b->point())));
  }
};

/// A cell slot or a list entry as a hash key (the map mixes the bits).
struct Slot_hash
{
  std::size_t operator()(std::uint32_t k) const { return k; }
};

/// A facet by the slots of its three vertices, in increasing order: half the
/// size of a `Facet_key`, for tables that hold many facets.
struct Vertex_slot_triple
{
  std::uint32_t a, b, c;
  friend bool operator==(const Vertex_slot_triple& x, const Vertex_slot_triple& y)
  {
    return x.a == y.a && x.b == y.b && x.c == y.c;
  }
};

typedef std::array<std::uint32_t, 4> Vertex_slot_quadruple;

struct Vertex_slot_triple_hash
{
  std::size_t operator()(const Vertex_slot_triple& t) const
  {
    return std::size_t((std::uint64_t(t.a) << 32 | t.b) ^ rotate_left(t.c, 17));
  }
};

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_DRIVER_SETTINGS_H
