// SPDX-License-Identifier: GPL-3.0-or-later
// Benchmark (not a test): the places where the package keeps code of its own
// beside a library that does the same, each measured against that library in
// one run:
//   flips  the package's 2-3 and 3-2 flips (of a facet, as the Lawson pass and
//          flip insertion make them; execute_flip of a plan: glued directly,
//          and by matching facets, the path of every other plan) against CGAL's
//          Triangulation_data_structure_3::flip_flippable, on the same facets,
//          planned in the timed loop, and (as in the drivers, whose criterion
//          decides on the plan) with the plans made beforehand;
//   index  the slot number of a cell: internal::Compact_container_index
//          against CGAL's Compact_container::index;
//   map    the drivers' hash map (internal::Flat_hash_map) against
//          std::unordered_map and boost::unordered_map, on a driver's pattern
//          (32-bit keys, finds, inserts and erases mixed).
//
//   benchmark_library_choices [N [ROUNDS]]   (default 1000000 points, 5 rounds)

#include "benchmark_common.h"
#include <CGAL/Edge_swapping_3/internal/common_flips.h>
#include <CGAL/Edge_swapping_3/internal/compact_container_index.h>
#include <CGAL/Edge_swapping_3/internal/flat_hash_map.h>
#include <CGAL/Edge_swapping_3/delaunay_by_insertion.h>
#include <CGAL/Triangulation_3.h>
#include <boost/unordered_map.hpp>
#include <boost/version.hpp>
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <random>
#include <set>
#include <string>
#include <unordered_map>

namespace {

typedef CGAL::Triangulation_3<K> Tr;
typedef Tr::Cell_handle Cell_handle;

// Facets of `tr` that a 2-3 flip makes, no two sharing a cell, in storage order.
std::vector<std::pair<Cell_handle, int>> disjoint_2_3_facets(Tr& tr)
{
  std::vector<std::pair<Cell_handle, int>> facets;
  std::set<Cell_handle> used;
  for(Cell_handle c : tr.finite_cell_handles())
    for(int i = 0; i < 4; ++i)
    {
      const Cell_handle n = c->neighbor(i);
      if(used.count(c) || used.count(n) || tr.is_infinite(n)) continue;
      if(ES::internal::common_flip_at(tr, c, i).kind != ES::internal::COMMON_FLIP_2_3) continue;
      facets.emplace_back(c, i);
      used.insert(c);
      used.insert(n);
    }
  return facets;
}

enum Flipper { DIRECT, MATCHING, CGAL_TDS, COMMON };

// Every facet flipped 2-3, then every new edge flipped back 3-2; the seconds
// of the flips alone, the plans made before each phase's timer (ours) or the
// flips found by CGAL's flip itself.
double flip_phases(Tr& tr, const std::vector<std::pair<Cell_handle, int>>& facets, bool cgal)
{
  typedef Tr::Vertex_handle Vertex_handle;
  std::vector<std::pair<Vertex_handle, Vertex_handle>> edges;
  for(const auto& [c, i] : facets) edges.emplace_back(c->vertex(i), c->neighbor(i)->vertex(c->neighbor(i)->index(c)));
  std::vector<ES::Flip_plan<Tr>> plans(facets.size());
  std::array<Cell_handle, 4> made;
  std::vector<Cell_handle> around(facets.size());
  CGAL::Real_timer timer;
  if(cgal)
  {
    timer.start();
    for(const auto& [c, i] : facets) tr.tds().flip_flippable(c, i); // c holds the new edge (d, e)
    for(std::size_t k = 0; k < facets.size(); ++k)
    {
      const Cell_handle c = facets[k].first;
      tr.tds().flip_flippable(c, c->index(edges[k].first), c->index(edges[k].second));
    }
    return timer.time();
  }
  for(std::size_t k = 0; k < facets.size(); ++k) ES::internal::plan_flip_2_3(plans[k], facets[k].first, facets[k].second);
  timer.start();
  for(std::size_t k = 0; k < facets.size(); ++k)
  {
    ES::execute_flip(tr, plans[k], made);
    around[k] = made[0];
  }
  timer.stop();
  for(std::size_t k = 0; k < facets.size(); ++k)
  {
    const Cell_handle m = around[k];
    int inner[2], n_inner = 0;
    for(int l = 0; l < 4; ++l)
      if(m->vertex(l) != edges[k].first && m->vertex(l) != edges[k].second) inner[n_inner++] = l;
    ES::internal::plan_flip_3_2(plans[k], m, inner[0], inner[1]);
  }
  timer.start();
  for(std::size_t k = 0; k < facets.size(); ++k) ES::execute_flip(tr, plans[k], made);
  return timer.time();
}

// Each facet flipped 2-3 and straight back 3-2 (around the new edge); the
// seconds of the flips alone (the facets are found before).
double flip_pairs(Tr& tr, const std::vector<std::pair<Cell_handle, int>>& facets, Flipper how)
{
  CGAL::Real_timer timer;
  timer.start();
  ES::Flip_plan<Tr> plan;
  std::array<Cell_handle, 4> made;
  for(const auto& [c, i] : facets)
  {
    const auto d = c->vertex(i);
    const auto e = c->neighbor(i)->vertex(c->neighbor(i)->index(c));
    if(how == CGAL_TDS)
    {
      tr.tds().flip_flippable(c, i); // c holds the new edge (d, e)
      tr.tds().flip_flippable(c, c->index(d), c->index(e));
      continue;
    }
    if(how == COMMON)
    {
      // The flip of the Lawson pass and of flip insertion: no plan made.
      ES::internal::make_common_flip(tr, c, i, {ES::internal::COMMON_FLIP_2_3}, made);
      const Cell_handle m = made[0];
      int inner[2], n_inner = 0;
      for(int k = 0; k < 4; ++k)
        if(m->vertex(k) != d && m->vertex(k) != e) inner[n_inner++] = k;
      ES::internal::make_common_flip(tr, m, inner[0], {ES::internal::COMMON_FLIP_3_2, inner[1]}, made);
      continue;
    }
    ES::internal::plan_flip_2_3(plan, c, i);
    if(how == MATCHING) plan.facet_index = -1;
    ES::execute_flip(tr, plan, made);
    // Back: the three new cells around (d, e); made[0] holds it, and its
    // facets opposite the other two corners are those of made[1] and made[2].
    const Cell_handle m = made[0];
    int inner[2], n_inner = 0;
    for(int k = 0; k < 4; ++k)
      if(m->vertex(k) != d && m->vertex(k) != e) inner[n_inner++] = k;
    // The 3-2 plan wants the facet across which the apex lies first: either
    // inner facet serves, the other is the reflex one.
    ES::internal::plan_flip_3_2(plan, m, inner[0], inner[1]);
    if(how == MATCHING) plan.facet_index = plan.reflex_index = -1;
    ES::execute_flip(tr, plan, made);
  }
  return timer.time();
}

template <class Map>
double map_pattern(Map& map, std::size_t keys, std::size_t operations, std::size_t& checksum)
{
  std::mt19937 rng(1);
  std::vector<std::uint32_t> live;
  live.reserve(keys);
  CGAL::Real_timer timer;
  timer.start();
  for(std::size_t k = 0; k < keys; ++k)
  {
    const std::uint32_t key = std::uint32_t(rng());
    map[key] = std::uint32_t(k);
    live.push_back(key);
  }
  for(std::size_t k = 0; k < operations; ++k)
  {
    const std::uint32_t r = std::uint32_t(rng());
    switch(r & 3)
    {
    case 0: // a hit
    {
      const auto it = map.find(live[r % live.size()]);
      if(it != map.end()) checksum += it->second;
      break;
    }
    case 1: // most likely a miss
      checksum += map.find(r) != map.end();
      break;
    case 2: // erase a live key, insert another
    {
      const std::size_t at = (r >> 2) % live.size();
      map.erase(live[at]);
      live[at] = std::uint32_t(rng());
      map[live[at]] = std::uint32_t(k);
      break;
    }
    default:
      map[live[(r >> 2) % live.size()]] += 1;
    }
  }
  return timer.time();
}

// The same pattern through Flat_hash_map's interface (find gives a pointer).
double ours_pattern(std::size_t keys, std::size_t operations, std::size_t& checksum)
{
  struct Hash
  {
    std::size_t operator()(std::uint32_t k) const { return k; }
  };
  ES::internal::Flat_hash_map<std::uint32_t, std::uint32_t, Hash> map;
  std::mt19937 rng(1);
  std::vector<std::uint32_t> live;
  live.reserve(keys);
  CGAL::Real_timer timer;
  timer.start();
  for(std::size_t k = 0; k < keys; ++k)
  {
    const std::uint32_t key = std::uint32_t(rng());
    map[key] = std::uint32_t(k);
    live.push_back(key);
  }
  for(std::size_t k = 0; k < operations; ++k)
  {
    const std::uint32_t r = std::uint32_t(rng());
    switch(r & 3)
    {
    case 0:
      if(const auto* v = map.find(live[r % live.size()])) checksum += *v;
      break;
    case 1:
      checksum += map.find(r) != nullptr;
      break;
    case 2:
    {
      const std::size_t at = (r >> 2) % live.size();
      map.erase(live[at]);
      live[at] = std::uint32_t(rng());
      map[live[at]] = std::uint32_t(k);
      break;
    }
    default:
      map[live[(r >> 2) % live.size()]] += 1;
    }
  }
  return timer.time();
}

} // namespace

int main(int argc, char** argv)
{
  start_benchmark(argv);
  const std::size_t n = argc > 1 ? std::stoul(argv[1]) : 1000000;
  const int rounds = argc > 2 ? std::stoi(argv[2]) : 5;
  std::printf("benchmark_library_choices %zu %d\n", n, rounds);
  const auto points = random_points(n, 1);

  // Flips: the same facets of the same triangulation, in a child each; the
  // ways taken in turn, `rounds` times, so that a slow spell of the machine
  // falls on all of them, and each reported by its median.
  {
    Tr start;
    ES::delaunay_by_insertion(start, points);
    const std::size_t pairs = disjoint_2_3_facets(start).size();
    struct Way
    {
      const char* name;
      bool phases;
      Flipper how;
      std::vector<double> seconds;
      bool valid = true;
    };
    std::vector<Way> ways = {{"CGAL flip_flippable", false, CGAL_TDS, {}},
                             {"ours, direct, of a facet (no plan)", false, COMMON, {}},
                             {"ours, execute_flip glued directly", false, DIRECT, {}},
                             {"ours, execute_flip by matching", false, MATCHING, {}},
                             {"CGAL flip_flippable", true, CGAL_TDS, {}},
                             {"ours, execute_flip of a plan", true, DIRECT, {}}};
    for(int round = 0; round < rounds; ++round)
      for(Way& way : ways)
      {
        const Measure m = in_child([&](double* out) {
          Tr tr = start;
          const auto facets = disjoint_2_3_facets(tr);
          out[0] = way.phases ? flip_phases(tr, facets, way.how == CGAL_TDS) : flip_pairs(tr, facets, way.how);
          out[1] = tr.is_valid() ? 1 : 0;
        });
        way.seconds.push_back(m.values[0]);
        way.valid = way.valid && m.values[1] == 1;
      }
    auto median = [](std::vector<double> v) {
      std::sort(v.begin(), v.end());
      return v[v.size() / 2];
    };
    std::printf("\nflips: %zu facets of the Delaunay triangulation of %zu random points, each flipped 2-3 and back 3-2;"
                " median of %d rounds (min, max)\n",
                pairs, n, rounds);
    std::printf("  %-34s %9s %12s %6s\n", "flip", "s", "ns a flip", "valid");
    double cgal_s = 0;
    for(const Way& way : ways)
    {
      if(way.phases && way.how == CGAL_TDS)
        std::printf("  all 2-3 flips, then all 3-2 flips back; our plans made before each phase's timer:\n");
      const double s = median(way.seconds);
      if(way.how == CGAL_TDS) cgal_s = s;
      std::printf("  %-34s %9.3f %12.1f %6s   ratio to CGAL %.2f   (%.3f, %.3f)\n", way.name, s,
                  1e9 * s / (2.0 * pairs), way.valid ? "yes" : "NO", s / cgal_s,
                  *std::min_element(way.seconds.begin(), way.seconds.end()),
                  *std::max_element(way.seconds.begin(), way.seconds.end()));
    }
  }

  // The slot index of every cell, in random order.
  {
    Tr tr;
    ES::delaunay_by_insertion(tr, points);
    std::vector<Cell_handle> cells(tr.all_cell_handles().begin(), tr.all_cell_handles().end());
    std::shuffle(cells.begin(), cells.end(), std::mt19937(2));
    const std::size_t lookups = (std::min)(cells.size(), std::size_t(1000000));
    std::printf("\nindex: the slot numbers of %zu cells in random order, of %zu\n", lookups, cells.size());
    std::size_t sum_ours = 0, sum_cgal = 0;
    CGAL::Real_timer t;
    t.start();
    ES::internal::Compact_container_index<Tr::Triangulation_data_structure::Cell_range> index(tr.tds().cells());
    for(std::size_t k = 0; k < lookups; ++k) sum_ours += index(cells[k]);
    const double ours = t.time();
    t.reset();
    for(std::size_t k = 0; k < lookups; ++k) sum_cgal += tr.tds().cells().index(cells[k]);
    const double cgal = t.time();
    std::printf("  %-34s %9.3f s\n  %-34s %9.3f s   ratio to CGAL %.3f   same numbers: %s\n",
                "CGAL Compact_container::index", cgal, "ours, Compact_container_index", ours, ours / cgal,
                sum_ours == sum_cgal ? "yes" : "NO");
  }

  // The hash maps.
  {
    const std::size_t keys = 1 << 17, operations = 20000000;
    std::printf("\nmap: %zu live 32-bit keys, %zu operations (1/4 hits, 1/4 misses, 1/4 erase+insert, 1/4 updates)\n",
                keys, operations);
    std::size_t c1 = 0, c2 = 0, c3 = 0;
    std::unordered_map<std::uint32_t, std::uint32_t> std_map;
    const double s_std = map_pattern(std_map, keys, operations, c1);
    boost::unordered_map<std::uint32_t, std::uint32_t> boost_map;
    const double s_boost = map_pattern(boost_map, keys, operations, c2);
    const double s_ours = ours_pattern(keys, operations, c3);
    std::printf("  %-34s %9.3f s\n", "std::unordered_map", s_std);
    std::printf("  %-34s %9.3f s   (Boost %s)\n", "boost::unordered_map", s_boost, BOOST_LIB_VERSION);
    std::printf("  %-34s %9.3f s   ratio to std %.2f, to Boost %.2f   same answers: %s\n",
                "ours, Flat_hash_map", s_ours, s_ours / s_std, s_ours / s_boost,
                c1 == c2 && c2 == c3 ? "yes" : "NO");
  }
  return 0;
}
