// SPDX-License-Identifier: GPL-3.0-or-later
// A swap criterion of one's own: any function object that, given a swappable
// five-point configuration, says whether its alternative triangulation is
// better. Here: prefer the triangulation whose largest cell volume is smaller
// (spread volume evenly), with a tolerance, since volumes are computed in doubles.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/edge_swapping_3.h>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_3<K> Triangulation;
namespace ES = CGAL::Edge_swapping_3;

struct Smaller_largest_volume
{
  template <class Tr>
  bool operator()(const Tr& tr, const ES::Five_point_configuration<Tr>& conf) const
  {
    auto volume = [](const K::Point_3& a, const K::Point_3& b, const K::Point_3& c, const K::Point_3& d) {
      return CGAL::volume(a, b, c, d);
    };
    // The largest volume in the current and in the alternative triangulation.
    const auto [current, alternative] = ES::worst_current_and_alternative(tr, conf, volume, true);
    return alternative < current * (1 - 1e-9);
  }
};

double largest_volume(const Triangulation& tr)
{
  double v = 0;
  for(auto c : tr.finite_cell_handles()) v = (std::max)(v, tr.tetrahedron(c).volume());
  return v;
}

int main()
{
  CGAL::Random rng(7);
  std::vector<K::Point_3> points;
  for(int i = 0; i < 2000; ++i) points.emplace_back(rng.get_double(), rng.get_double(), rng.get_double());
  Triangulation tr;
  ES::insert_by_placing(tr, points);

  const double before = largest_volume(tr);
  const ES::Swap_report report = CGAL::swap_edges(tr, Smaller_largest_volume());
  const double after = largest_volume(tr);
  std::cout << "largest cell volume " << before << " -> " << after << " (" << ES::swap_ending_name(report.ending)
            << ", " << report.number_of_cycles() << " cycles)\n";
  return (tr.is_valid() && after <= before) ? 0 : 1;
}
