// SPDX-License-Identifier: GPL-3.0-or-later
// From an arbitrary triangulation to the Delaunay triangulation by edge
// swapping with the helper strategy, checked against CGAL cell for cell.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/edge_swapping_3.h>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_3<K> Triangulation;
namespace ES = CGAL::Edge_swapping_3;

int main()
{
  CGAL::Random rng(42);
  std::vector<K::Point_3> points;
  for(int i = 0; i < 5000; ++i)
    points.emplace_back(rng.get_double(), rng.get_double(), rng.get_double());

  Triangulation tr;
  ES::insert_by_placing(tr, points); // no flip: an arbitrary triangulation

  // The work queue (the default schedule) in a random face order, seed 0.
  const ES::Swap_report report =
    CGAL::swap_edges_with_helper(tr, ES::parameters::face_order(ES::RANDOM_ORDER, CGAL::parameters::random_seed(0)));

  const ES::Delaunay_comparison cmp = ES::compare_with_delaunay(tr);
  std::cout << ES::swap_ending_name(report.ending) << " after " << report.number_of_cycles()
            << " rounds; equal to CGAL's Delaunay triangulation: " << (cmp.identical ? "yes" : "no") << '\n';
  return cmp.identical ? 0 : 1;
}
