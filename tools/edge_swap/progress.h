// SPDX-License-Identifier: GPL-3.0-or-later
// Progress on standard error: at most a line a second, from the first second on.

#ifndef EDGE_SWAP_PROGRESS_H
#define EDGE_SWAP_PROGRESS_H

#include <CGAL/Edge_swapping_3/Swap_report.h>
#include <CGAL/Real_timer.h>
#include <iostream>
#include <memory>
#include <string>

namespace edge_swap {

inline std::function<void(const CGAL::Edge_swapping_3::Cycle_record&)> cycle_progress(const std::string& what)
{
  auto timer = std::make_shared<CGAL::Real_timer>();
  auto next = std::make_shared<double>(1.0);
  timer->start();
  return [timer, next, what](const CGAL::Edge_swapping_3::Cycle_record& r) {
    if(timer->time() < *next) return;
    *next = timer->time() + 1.0;
    std::cerr << what << ": cycle " << r.cycle << ", swaps 2-3 " << r.swaps[0] << ", 3-2 " << r.swaps[1]
              << ", 2-2 " << r.swaps[2] << ", 4-4 " << r.swaps[3] << ", cells " << r.cells << " ("
              << timer->time() << " s)\n";
  };
}

} // namespace edge_swap

#endif
