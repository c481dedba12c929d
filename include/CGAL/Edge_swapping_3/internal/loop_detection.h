// SPDX-License-Identifier: GPL-3.0-or-later
// A state that comes back, under the fixed face order.
//
// Under the fixed order a cycle is a function of the state it starts from:
// the cells by their vertices, their tags, and the tags the reading
// remembers by vertices (the order is one of vertex triples; a rule that
// says `reads_only_cells_and_tags` reads nothing else). When the state at
// the end of cycle i is that of cycle i - p, the run repeats its last p
// cycles until the limit: their records are added again for each whole
// period left, and the cycles left over are run, so that the report and the
// triangulation at the end are those of running every cycle. Brent's
// method finds p on hashes of the states (a sum over the cells): one
// cycle's hash is kept and compared with each later one's, and the kept one
// moves on after 1, 2, 4, ... cycles. A match is only likely: the state of
// that cycle is kept and compared, exactly, with the state p cycles on. So
// no state is held but on a likely loop (a mesh's cells, 20 bytes each).

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_LOOP_DETECTION_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_LOOP_DETECTION_H

#include <CGAL/Edge_swapping_3/internal/driver_visits.h>
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// Under the fixed face order, a state that comes back ends the work of a
/// run whose rule reads only the cells and the tags: the cycles to the limit
/// are added up, not run.
template <class Base>
class Loop_detection : public Base
{
protected:
  CGAL_EDGE_SWAPPING_3_DRIVER_STATE_NAMES

  Loop_detection(Tr& tr, const Driver_settings& settings) : Base(tr, settings) {}

  /// A run starts: `on` when the run may skip repeated cycles.
  void start_loop_detection(bool on)
  {
    skip_repeats_ = on;
    kept_round_ = 0;
    kept_for_ = 1;
    candidate_round_ = 0;
    round_hashes_.clear();
  }

  struct Cycle_state
  {
    std::vector<std::array<std::uint32_t, 5>> cells; // vertex slots in increasing order, then the tag
    std::size_t remembered = 0; // remembered tags: a set that only grows, so its size tells it
    bool operator==(const Cycle_state& o) const { return remembered == o.remembered && cells == o.cells; }
  };

  std::array<std::uint32_t, 5> cell_state(Cell_handle c)
  {
    const Vertex_slot_quadruple q = vertex_slots(c);
    return {q[0], q[1], q[2], q[3], std::uint32_t(is_tagged(c))};
  }

  std::uint64_t state_hash()
  {
    std::uint64_t h = mix_bits(remembered_tags_.size());
    for(Cell_handle c : tr_.finite_cell_handles())
    {
      std::uint64_t g = 0;
      for(std::uint32_t x : cell_state(c)) g = mix_bits(g ^ x);
      h += g; // a sum: the cells in any order
    }
    return h;
  }

  Cycle_state cycle_state()
  {
    Cycle_state s;
    s.remembered = remembered_tags_.size();
    for(Cell_handle c : tr_.finite_cell_handles()) s.cells.push_back(cell_state(c));
    std::sort(s.cells.begin(), s.cells.end());
    return s;
  }

  /// After cycle `round`, which did not end the run: the cycle the run is at,
  /// `round` or later if the state came back (the cycles between added up).
  std::size_t skip_repeated_cycles(Swap_report& report, std::size_t round)
  {
    const std::uint64_t h = state_hash();
    round_hashes_.push_back(h); // of round round_hashes_.size()
    if(candidate_round_ > 0 && round == candidate_round_ + candidate_period_)
    {
      if(h == candidate_hash_ && cycle_state() == candidate_state_)
        return add_periods(report, round, candidate_period_);
      candidate_round_ = 0; // two states with one hash
      candidate_state_ = Cycle_state();
    }
    if(candidate_round_ == 0 && kept_round_ > 0 && h == kept_hash_)
    {
      candidate_state_ = cycle_state();
      candidate_hash_ = h;
      candidate_round_ = round;
      candidate_period_ = round - kept_round_;
    }
    if(round - kept_round_ == kept_for_)
    {
      kept_hash_ = h;
      kept_round_ = round;
      kept_for_ *= 2;
    }
    return round;
  }

  /// The state at the end of cycle `round` is that of `period` cycles before:
  /// the whole periods left are added up; returns the cycle they end on.
  std::size_t add_periods(Swap_report& report, std::size_t round, std::size_t period)
  {
    const std::size_t added = (settings_.max_rounds - round) / period * period;
    for(std::size_t k = 1; k <= added; ++k)
    {
      Cycle_record r = report.cycles[report.cycles.size() - period]; // a copy: the vector grows
      r.cycle = round + k;
      report.cycles.push_back(r);
      if(settings_.cycle_visitor) settings_.cycle_visitor(r);
    }
    if(settings_.cycles_skipped != nullptr) *settings_.cycles_skipped += added;
    locate_loop(report, period);
    skip_repeats_ = false; // fewer cycles than a period are left
    candidate_state_ = Cycle_state();
    return round + added;
  }

  /// The run loops with a period dividing `period` (states compared exactly):
  /// the report gets where it first came back, by the rounds' hashes (the
  /// first round i whose hash is that of round i + `period`, then the
  /// shortest period from there; hashes equal by chance would misplace it).
  void locate_loop(Swap_report& report, std::size_t period)
  {
    const std::vector<std::uint64_t>& h = round_hashes_; // h[k]: after round k + 1
    std::size_t i = 0;
    while(h[i] != h[i + period]) ++i; // ends: the last round's hash is that of `period` before
    std::size_t p = 1;
    while(period % p != 0 || h[i] != h[i + p]) ++p;
    report.loop_round = i + 1 + p;
    report.loop_period = p;
    round_hashes_ = {};
  }


  // skip_repeated_cycles: on in this run; the hash kept, its cycle (0: none) and
  // the cycles until it moves on; a likely loop: the state, hash and cycle (0:
  // none) to find again, and the period after which to look.
  bool skip_repeats_ = false;
  std::uint64_t kept_hash_ = 0;
  std::size_t kept_round_ = 0;
  std::size_t kept_for_ = 1;
  Cycle_state candidate_state_;
  std::uint64_t candidate_hash_ = 0;
  std::size_t candidate_round_ = 0;
  std::size_t candidate_period_ = 0;
  std::vector<std::uint64_t> round_hashes_; // the state's hash after each round, to place a loop
};

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

// The names of Loop_detection in a layer derived from it (`Base`).
#define CGAL_EDGE_SWAPPING_3_LOOP_DETECTION_NAMES \
  using Base::skip_repeats_; \
  using Base::skip_repeated_cycles;

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_LOOP_DETECTION_H
