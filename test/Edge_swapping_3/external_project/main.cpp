// SPDX-License-Identifier: GPL-3.0-or-later
// The README's example, built against the installed package.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/edge_swapping_3.h>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace ES = CGAL::Edge_swapping_3;

int main()
{
  CGAL::Random rng(42);
  std::vector<K::Point_3> points;
  for(int i = 0; i < 2000; ++i) points.emplace_back(rng.get_double(), rng.get_double(), rng.get_double());

  CGAL::Triangulation_3<K> tr;
  ES::insert_by_placing(tr, points);
  const ES::Swap_report report = CGAL::swap_edges_with_helper(tr);
  const bool identical = ES::compare_with_delaunay(tr).identical;
  std::cout << report.number_of_cycles() << " rounds, " << (identical ? "equal to" : "differs from")
            << " CGAL's Delaunay triangulation\n";
  return identical ? 0 : 1;
}
