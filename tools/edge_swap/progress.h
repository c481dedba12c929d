// SPDX-License-Identifier: GPL-3.0-or-later
// Progress on standard error: at most a line a second, from the first second
// on; `--quiet` turns it off.

#ifndef EDGE_SWAP_PROGRESS_H
#define EDGE_SWAP_PROGRESS_H

#include <CGAL/Edge_swapping_3/Swap_report.h>
#include <CGAL/Real_timer.h>
#include <iostream>
#include <memory>
#include <string>
#include <vector>
#include <functional>

namespace edge_swap {

/// `--quiet`: no progress lines.
inline bool quiet = false;

inline std::function<void(const CGAL::Edge_swapping_3::Cycle_record&)> cycle_progress(const std::string& what)
{
  auto timer = std::make_shared<CGAL::Real_timer>();
  auto next = std::make_shared<double>(1.0);
  timer->start();
  return [timer, next, what](const CGAL::Edge_swapping_3::Cycle_record& r) {
    if(quiet || timer->time() < *next) return;
    *next = timer->time() + 1.0;
    std::cerr << what << ": cycle " << r.cycle << ", swaps 2-3 " << r.swaps[0] << ", 3-2 " << r.swaps[1]
              << ", 2-2 " << r.swaps[2] << ", 4-4 " << r.swaps[3] << ", cells " << r.cells << " ("
              << timer->time() << " s)\n";
  };
}

/// The worst-first driver's progress (a `ReplacementVisitor_3`): the
/// operations done, the measure of the cell it works on (it takes the worst
/// first, so this is about the worst of the mesh), the time.
template <class Criterion>
class Worst_first_progress
{
public:
  explicit Worst_first_progress(const Criterion& criterion) : criterion_(criterion) { state_->timer.start(); }

  template <class Tr>
  void before_replacement(const Tr&, const std::vector<typename Tr::Cell_handle>& cells) const
  {
    ++state_->operations;
    if(!cells.empty()) report(cells.front());
  }
  template <class Tr>
  void after_replacement(const Tr&, const std::vector<typename Tr::Cell_handle>&) const {}
  template <class Tr>
  void after_move(const Tr&, typename Tr::Vertex_handle v, const typename Tr::Point&) const
  {
    ++state_->operations;
    report(v->cell());
  }

private:
  template <class Cell_handle>
  void report(Cell_handle c) const
  {
    if(quiet || state_->timer.time() < state_->next) return;
    state_->next = state_->timer.time() + 1.0;
    std::cerr << "worst first: " << state_->operations << " operations, at a cell of "
              << criterion_.measure(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(),
                                    c->vertex(3)->point())
              << " (" << state_->timer.time() << " s)\n";
  }
  struct State
  {
    CGAL::Real_timer timer;
    double next = 1.0;
    std::size_t operations = 0;
  };
  Criterion criterion_;
  std::shared_ptr<State> state_ = std::make_shared<State>(); // the driver copies its visitor
};

} // namespace edge_swap

#endif
