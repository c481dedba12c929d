// SPDX-License-Identifier: GPL-3.0-or-later
// Benchmark (not a test): a Delaunay triangulation built from scratch by
// flip-based insertion in spatial order, beside CGAL's Delaunay_triangulation_3
// (Bowyer-Watson) and TetGen on the same points, in one run, each in its own
// process. Checks that ours equals CGAL's cell for cell.
//
//   benchmark_insertion_vs_cgal [N ...]        (default: 100000 1000000)
//   benchmark_insertion_vs_cgal --count N      in-sphere and orientation tests per point,
//                                              ours and CGAL's, through a counting kernel

#include <CGAL/Real_timer.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/Edge_swapping_3/Delaunay_comparison.h>
#include <CGAL/Edge_swapping_3/delaunay_by_insertion.h>
#include "benchmark_common.h"

typedef CGAL::Triangulation_3<K> Triangulation;

// The kernel, counting the exact predicates the triangulations ask of it.
// (Ours decides most link-flip orientations in one batch under a static
// filter, which does not go through the kernel: only its fallbacks count.)
struct Counts { std::size_t in_sphere = 0, orientation = 0; };
Counts counts;
struct Counting_kernel : K
{
  struct Side_of_oriented_sphere_3
  {
    typedef CGAL::Oriented_side result_type;
    template <class... P> result_type operator()(const P&... p) const
    {
      ++counts.in_sphere;
      return K().side_of_oriented_sphere_3_object()(p...);
    }
  };
  struct Orientation_3
  {
    typedef CGAL::Orientation result_type;
    template <class... P> result_type operator()(const P&... p) const
    {
      ++counts.orientation;
      return K().orientation_3_object()(p...);
    }
  };
  Side_of_oriented_sphere_3 side_of_oriented_sphere_3_object() const { return {}; }
  Orientation_3 orientation_3_object() const { return {}; }
};

int count_predicates(std::size_t n)
{
  const auto points = random_points(n);
  CGAL::Triangulation_3<Counting_kernel> tr;
  const auto totals = ES::delaunay_by_insertion(tr, points);
  const Counts ours = counts;
  counts = Counts();
  CGAL::Delaunay_triangulation_3<Counting_kernel> dt(points.begin(), points.end());
  const auto& s = totals.swaps;
  std::printf("%zu points, per point: flips %.2f (2-3 %.2f, 3-2 %.2f)\n", n, double(s[0] + s[1] + s[2] + s[3]) / n,
              double(s[0]) / n, double(s[1]) / n);
  std::printf("  in-sphere tests: ours %.2f, CGAL %.2f\n", double(ours.in_sphere) / n, double(counts.in_sphere) / n);
  std::printf("  orientation tests through the kernel: ours %.2f, CGAL %.2f\n", double(ours.orientation) / n,
              double(counts.orientation) / n);
  return 0;
}

int main(int argc, char** argv)
{
  if(argc == 3 && std::string(argv[1]) == "--count") return count_predicates(std::stoul(argv[2]));
  std::vector<std::size_t> sizes;
  for(int a = 1; a < argc; ++a) sizes.push_back(std::stoul(argv[a]));
  if(sizes.empty()) sizes = {100000, 1000000};

  std::printf("%9s | %8s %7s | %8s %7s | %8s %7s %10s %10s | %7s %7s | %s\n", "points", "CGAL s", "MiB", "TetGen s",
              "MiB", "ours s", "MiB", "flips", "flips/pt", "t ratio", "m ratio", "equal to CGAL");
  for(std::size_t n : sizes)
  {
    const Measure cgal = in_child([n](double* out) { cgal_delaunay(n, out); });
    const Measure tet = in_child([n](double* out) { tetgen(n, out); });
    const Measure ours = in_child([n](double* out) {
      const auto points = random_points(n);
      Triangulation tr;
      const auto totals = ES::delaunay_by_insertion(tr, points);
      out[0] = totals.seconds;
      const auto& s = totals.swaps;
      out[1] = double(s[0] + s[1] + s[2] + s[3]);
      out[2] = double(totals.stuck_facets);
      struct rusage usage;
      getrusage(RUSAGE_SELF, &usage);
      out[4] = double(usage.ru_maxrss) / 1024.0; // before the comparison builds CGAL's too
      out[3] = ES::compare_with_delaunay(tr).identical ? 1 : 0;
    });
    std::printf("%9zu | %8.2f %7.0f | %8.2f %7.0f | %8.2f %7.0f %10.0f %10.2f | %7.2f %7.2f | %s\n", n,
                cgal.values[0], cgal.peak_mib, tet.values[0], tet.values[1], ours.values[0], ours.values[4],
                ours.values[1], ours.values[1] / double(n), ours.values[0] / cgal.values[0],
                ours.values[4] / cgal.peak_mib, ours.values[3] == 1 ? "yes" : "NO");
    std::fflush(stdout);
  }
  return 0;
}
