// SPDX-License-Identifier: GPL-3.0-or-later
// Must not compile: the drivers refuse a kernel whose predicates round
// (the test `inexact_kernel_refused` requires the static assertion's message).

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/edge_swapping_3.h>

int main()
{
  CGAL::Triangulation_3<CGAL::Simple_cartesian<double>> tr;
  CGAL::swap_edges(tr, CGAL::Edge_swapping_3::Delaunay_criterion());
  return 0;
}
