// SPDX-License-Identifier: GPL-3.0-or-later
// Benchmark (not a test): the helper strategy from a placing start to the
// Delaunay triangulation, beside CGAL's Delaunay_triangulation_3 and TetGen's
// Delaunay on the same points, in one run. Each contender runs in a child
// process of its own, so that its peak memory is its own.
//
//   benchmark_helper_vs_cgal [--max-cycles C] [--stall-dir DIR] [--no-pure-helper] [--seed S]
//                            [--fixed-order-cycles F] [N ...]
//                            (default: 1000 cycles; seed 1; 100000 1000000)
//
// --seed S takes the points (for every contender) from CGAL::Random(S).
//
// --fixed-order-cycles F adds two lines per size: the helper on the paper's
// cycles in a fixed face order (PRIORITY_ORDER, seed S) for F cycles, with
// the driver's check for a state that comes back (on by default there) and
// without it: the price of the check's per-cycle state hash on a large mesh.
// The two are run in turn, three times each; the median of each is printed.
//
// --no-pure-helper leaves out the pure helper run (the longest: past 2,000 s
// at 10^6 points), keeping CGAL, TetGen and the repair.
//
// When the helper has not converged, --stall-dir writes the stalled region:
// DIR/stall_N.node/.ele, the cells around the facets that are still not
// locally Delaunay (every cell with a vertex on one), and DIR/stall_N.txt,
// each such facet with its five-point configuration and whether it is
// swappable: what keeps the helper from ending there. The progress on standard
// error gives, after each round, a hash of the set of cells: a repeat is named.
//
// A second line per size, "repair", gives the same placing start handed to
// `swap_edges` with the Delaunay criterion (plain flips first, the helper
// strategy only where they are stuck, a rebuild past its bound): the helper's
// schedule that makes the fewest swaps we found.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/edge_swapping_3.h>
#include <CGAL/Edge_swapping_3/Delaunay_comparison.h>
#include <CGAL/Edge_swapping_3/start_triangulations.h>
#include "benchmark_common.h"
#include <algorithm>
#include <array>
#include <iostream>
#include <map>
#include <set>

typedef CGAL::Triangulation_3<K> Triangulation;

namespace {

// The stalled region of `tr` (see above); returns the number of facets in it.
std::size_t write_stalled_region(const Triangulation& tr, const std::string& stem)
{
  std::vector<Triangulation::Facet> stalled;
  for(const auto& f : tr.finite_facets())
    if(!ES::is_locally_delaunay(tr, f.first, f.second)) stalled.push_back(f);
  std::map<Triangulation::Vertex_handle, std::size_t> index;
  std::set<Triangulation::Cell_handle> region;
  for(const auto& f : stalled)
    for(int k = 1; k < 4; ++k)
    {
      std::vector<Triangulation::Cell_handle> star;
      tr.finite_incident_cells(f.first->vertex((f.second + k) & 3), std::back_inserter(star));
      region.insert(star.begin(), star.end());
    }
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 4>> cells;
  auto number = [&](Triangulation::Vertex_handle v) {
    const auto it = index.emplace(v, points.size());
    if(it.second) points.push_back({v->point().x(), v->point().y(), v->point().z()});
    return it.first->second;
  };
  for(auto c : region) cells.push_back({number(c->vertex(0)), number(c->vertex(1)), number(c->vertex(2)), number(c->vertex(3))});
  std::ofstream node(stem + ".node"), ele(stem + ".ele"), text(stem + ".txt");
  ES::IO::write_node_file(node, points, {}, 0);
  ES::IO::write_ele_file(ele, cells, 0);
  text << "# facet (point indices in " << stem << ".node), configuration, swappable\n";
  for(const auto& f : stalled)
  {
    const auto conf = ES::classify_facet(tr, f.first, f.second);
    for(int k = 1; k < 4; ++k) text << number(f.first->vertex((f.second + k) & 3)) << ' ';
    text << ES::configuration_kind_name(conf.kind()) << ' ' << (conf.is_swappable() ? "yes" : "no") << '\n';
  }
  return stalled.size();
}

// An order-free hash of the set of cells (each cell by its vertices), kept
// through every flip: equal hashes after two rounds say the triangulation
// came back (up to a 2^-64 chance of collision), i.e. the run loops.
struct Cell_set_hash
{
  std::uint64_t value = 0;

  static std::uint64_t of(Triangulation::Cell_handle c)
  {
    std::array<std::uintptr_t, 4> v;
    for(int i = 0; i < 4; ++i) v[i] = ES::internal::address_of(c->vertex(i));
    std::sort(v.begin(), v.end());
    std::uint64_t h = 0;
    for(auto a : v) h = ES::internal::mix_bits(h ^ a);
    return h;
  }
  void before_flip(const Triangulation&, const ES::Flip_plan<Triangulation>& plan)
  {
    for(int k = 0; k < plan.number_of_old_cells; ++k) value -= of(plan.old_cells[k]);
  }
  void after_flip(const Triangulation&, const ES::Flip_plan<Triangulation>&,
                  const std::array<Triangulation::Cell_handle, 4>& created, int n)
  {
    for(int k = 0; k < n; ++k) value += of(created[k]);
  }
};

// The helper on the paper's cycles in the fixed order from a placing start;
// out: seconds, cycles, swaps, non-Delaunay facets left, cycles added up.
void fixed_order_helper(std::size_t n, int seed, std::size_t cycles, bool check_repeats, double* out)
{
  const auto points = random_points(n, seed);
  Triangulation tr;
  ES::insert_by_placing(tr, points);
  ES::internal::Driver_settings s;
  s.schedule = ES::PAPER_CYCLES;
  s.face_order = ES::PRIORITY_ORDER;
  s.random_seed = unsigned(seed);
  s.max_rounds = cycles;
  s.skip_repeated_cycles = check_repeats;
  std::size_t skipped = 0;
  s.cycles_skipped = &skipped;
  const ES::Swap_report report = ES::internal::with_domain_constraints(
    tr, CGAL::parameters::default_values(), [&](const auto& constraints) {
      return ES::internal::run_helper(tr, s, constraints, CGAL::parameters::default_values());
    });
  const auto w = report.total_swaps();
  out[0] = report.seconds;
  out[1] = double(report.number_of_cycles());
  out[2] = double(w[0] + w[1] + w[2] + w[3]);
  out[3] = double(report.non_delaunay_facets);
  out[4] = double(skipped);
}

double median_of_three(std::array<double, 3> v)
{
  std::sort(v.begin(), v.end());
  return v[1];
}

} // namespace

int main(int argc, char** argv)
{
  start_benchmark(argv);
  std::vector<std::size_t> sizes;
  std::size_t max_cycles = 1000;
  std::string stall_dir;
  bool pure_helper = true;
  int seed = 1;
  std::size_t fixed_order_cycles = 0;
  for(int a = 1; a < argc; ++a)
  {
    if(std::string(argv[a]) == "--max-cycles" && a + 1 < argc) max_cycles = std::stoul(argv[++a]);
    else if(std::string(argv[a]) == "--stall-dir" && a + 1 < argc) stall_dir = argv[++a];
    else if(std::string(argv[a]) == "--no-pure-helper") pure_helper = false;
    else if(std::string(argv[a]) == "--seed" && a + 1 < argc) seed = std::stoi(argv[++a]);
    else if(std::string(argv[a]) == "--fixed-order-cycles" && a + 1 < argc) fixed_order_cycles = std::stoul(argv[++a]);
    else sizes.push_back(std::stoul(argv[a]));
  }
  if(sizes.empty()) sizes = {100000, 1000000};

  std::printf("%9s | %8s %8s | %8s %8s | %8s %8s %6s %9s %8s | %7s %7s | %-9s %7s %s\n", "points", "CGAL s", "MiB",
              "TetGen s", "MiB", "place s", "helper s", "cycles", "swaps", "MiB", "t ratio", "m ratio", "ending",
              "non-Del", "equal");
  for(std::size_t n : sizes)
  {
    const Measure cgal = in_child([n, seed](double* out) { cgal_delaunay(n, out, seed); });
    const Measure tet = in_child([n, seed](double* out) { tetgen(n, out, seed); });
    const Measure ours = !pure_helper ? Measure() : in_child([n, seed, max_cycles, &stall_dir](double* out) {
      const auto points = random_points(n, seed);
      Triangulation tr;
      CGAL::Real_timer t;
      t.start();
      ES::insert_by_placing(tr, points);
      out[0] = t.time();
      CGAL::Real_timer clock;
      clock.start();
      Cell_set_hash cells;
      for(auto c : tr.all_cell_handles()) cells.value += Cell_set_hash::of(c);
      std::map<std::uint64_t, std::size_t> seen; // hash after a round: the first such round
      std::function<void(const ES::Cycle_record&)> progress = [&](const ES::Cycle_record& r) {
        std::cerr << "  round " << r.cycle << ": " << r.total_swaps() << " swaps, " << r.visits << " visits, "
                  << clock.time() << " s, cells hash " << std::hex << cells.value << std::dec;
        const auto first = seen.emplace(cells.value, r.cycle);
        if(!first.second) std::cerr << " (the triangulation after round " << first.first->second << ")";
        std::cerr << '\n';
      };
      // The work queue (the default), random face order.
      const ES::Swap_report report = CGAL::swap_edges_with_helper(
        tr, ES::parameters::cycle_visitor(progress, CGAL::parameters::random_seed(1).number_of_iterations(max_cycles).visitor(std::ref(cells))));
      Cell_set_hash recomputed;
      for(auto c : tr.all_cell_handles()) recomputed.value += Cell_set_hash::of(c);
      if(recomputed.value != cells.value) std::cerr << "  the hash kept through the flips is wrong\n";
      const auto s = report.total_swaps();
      out[1] = report.seconds;
      out[2] = double(report.number_of_cycles());
      out[3] = double(s[0] + s[1] + s[2] + s[3]);
      out[6] = double(report.ending);
      out[7] = double(report.non_delaunay_facets);
      struct rusage usage;
      getrusage(RUSAGE_SELF, &usage);
      out[5] = double(usage.ru_maxrss) / 1024.0; // peak before the comparison, which builds CGAL's too
      out[4] = ES::compare_with_delaunay(tr).identical ? 1 : 0; // not timed
      if(out[4] == 0 && !stall_dir.empty())
        std::cerr << "  stalled region: " << write_stalled_region(tr, stall_dir + "/stall_" + std::to_string(n))
                  << " facets not locally Delaunay, written to " << stall_dir << "/stall_" << n << ".*\n";
    });
    const Measure repair = in_child([n, seed](double* out) {
      Triangulation tr;
      const auto points = random_points(n, seed);
      CGAL::Real_timer t;
      t.start();
      ES::insert_by_placing(tr, points);
      out[8] = t.time();
      t.reset();
      const ES::Swap_report report = CGAL::swap_edges(tr, ES::Delaunay_criterion());
      out[0] = t.time();
      const auto s = report.total_swaps();
      out[1] = double(s[0] + s[1] + s[2] + s[3]);
      out[2] = double(report.number_of_cycles());
      out[3] = double(report.repair_path);
      out[4] = double(report.stuck_after_plain_flips);
      out[5] = double(report.helper_rounds);
      struct rusage usage;
      getrusage(RUSAGE_SELF, &usage);
      out[6] = double(usage.ru_maxrss) / 1024.0;
      out[7] = ES::compare_with_delaunay(tr).identical ? 1 : 0; // not timed
    });
    const double ours_seconds = ours.values[0] + ours.values[1];
    const int ending = int(ours.values[6]);
    if(pure_helper)
      std::printf("%9zu | %8.2f %8.0f | %8.2f %8.0f | %8.2f %8.2f %6.0f %9.0f %8.0f | %7.1f %7.1f | %-9s %7.0f %s\n", n,
                cgal.values[0], cgal.peak_mib, tet.values[0], tet.values[1], ours.values[0], ours.values[1], ours.values[2],
                ours.values[3], ours.values[5], ours_seconds / cgal.values[0], ours.values[5] / cgal.peak_mib,
                ending == ES::CONVERGED ? "converged" : ending == ES::STUCK ? "stuck" : "limit", ours.values[7],
                ours.values[4] == 1 ? "yes" : "no");
    std::printf("%9s   repair from the same placing start (placing %.2f s, CGAL %.2f s, TetGen %.2f s): %.2f s, %.0f rounds, %.0f swaps, %s (plain flips left %.0f "
                "facets, helper rounds %.0f), %.0f MiB, (placing + repair) / CGAL %.1f, memory / CGAL %.1f, equal to CGAL: %s\n",
                "", repair.values[8], cgal.values[0], tet.values[0], repair.values[0], repair.values[2], repair.values[1],
                ES::delaunay_repair_path_name(ES::Delaunay_repair_path(int(repair.values[3]))), repair.values[4],
                repair.values[5], repair.values[6], (repair.values[8] + repair.values[0]) / cgal.values[0],
                repair.values[6] / cgal.peak_mib, repair.values[7] == 1 ? "yes" : "no");
    if(fixed_order_cycles > 0)
    {
      std::array<std::array<double, 3>, 2> seconds;
      std::array<Measure, 2> last;
      for(int round = 0; round < 3; ++round)
        for(int check = 1; check >= 0; --check)
        {
          last[check] = in_child([n, seed, fixed_order_cycles, check](double* out) {
            fixed_order_helper(n, seed, fixed_order_cycles, check == 1, out);
          });
          seconds[check][round] = last[check].values[0];
        }
      for(int check = 1; check >= 0; --check)
        std::printf("%9s   fixed order, paper's cycles, state check %s: %.2f s (median of %.2f %.2f %.2f), %.0f cycles, %.0f "
                    "swaps, %.0f facets not Delaunay, %.0f cycles added up, %.0f MiB, per cycle / CGAL %.2f\n",
                    "", check ? "on " : "off", median_of_three(seconds[check]), seconds[check][0], seconds[check][1],
                    seconds[check][2], last[check].values[1], last[check].values[2], last[check].values[3],
                    last[check].values[4], last[check].peak_mib,
                    median_of_three(seconds[check]) / last[check].values[1] / cgal.values[0]);
      std::printf("%9s   the check's price: on / off %.3f\n", "", median_of_three(seconds[1]) / median_of_three(seconds[0]));
    }
    std::fflush(stdout);
  }
  return 0;
}
