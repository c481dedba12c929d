// SPDX-License-Identifier: GPL-3.0-or-later
// The worst-first driver's queue: the cells that wait for a visit, taken
// worst first, with only a batch of them in the heap at a time. The cells
// that score below a bound are in the heap; the others wait outside it, one
// byte each, and a sweep over those bytes takes in the next batch when the
// heap is empty. Every waiting cell in the heap scores below the bound and
// every one outside does not, so the cells come out in the order of a heap
// that held them all: the run is the same, the heap a fraction of the size.

#ifndef CGAL_EDGE_SWAPPING_3_INTERNAL_WORST_CELL_QUEUE_H
#define CGAL_EDGE_SWAPPING_3_INTERNAL_WORST_CELL_QUEUE_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <limits>
#include <optional>
#include <queue>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace internal {

/// A cell in the heap: its score (larger is better) rounded to float, and its
/// slot. Eight bytes: the score only schedules (every decision is the
/// criterion's own), and ties go to the smaller slot, which no address decides.
struct Worst_cell_entry
{
  float score;
  std::uint32_t slot;

  bool operator<(const Worst_cell_entry& other) const // std::priority_queue keeps the largest on top
  {
    return score != other.score ? score > other.score : slot > other.slot;
  }
};

class Worst_cell_queue
{
public:
  /// About `batch` cells in the heap at a time (at least 1).
  explicit Worst_cell_queue(std::size_t batch) : batch_((std::max)(batch, std::size_t(1))) {}

  /// Whether the cell in `slot` waits for a visit, in the heap or outside it.
  bool waits(std::size_t slot) const
  {
    return slot < state_.size() && (state_[slot] == queued || state_[slot] == deferred);
  }

  /// The cell in `slot` needs no visit until it changes (it meets the quality
  /// target): it is not measured again when pushed.
  void settle(std::size_t slot, std::size_t slots)
  {
    if(slot >= state_.size()) state_.resize((std::max)(slots, slot + 1), idle);
    leave(slot);
    state_[slot] = settled;
  }

  bool is_settled(std::size_t slot) const { return slot < state_.size() && state_[slot] == settled; }

  /// The cell in `slot` is visited, or changed: it waits no more (nor is it
  /// settled), and an entry of its slot left in the heap is passed over.
  void forget(std::size_t slot)
  {
    if(slot >= state_.size()) return;
    leave(slot);
    state_[slot] = idle;
  }

  /// The cell in `slot`, of `score`, waits (`slots` bounds every slot, for the per-slot bytes).
  void add(std::size_t slot, float score, std::size_t slots)
  {
    if(slot > std::numeric_limits<std::uint32_t>::max())
      throw std::length_error("Edge_swapping_3: more than 2^32 cells");
    if(slot >= state_.size()) state_.resize((std::max)(slots, slot + 1), idle);
    leave(slot);
    if(!(score >= bound_))
    {
      state_[slot] = queued;
      heap_.push(Worst_cell_entry{score, std::uint32_t(slot)});
    }
    else
    {
      state_[slot] = deferred;
      ++deferred_cells_;
      offer(score);
    }
  }

  bool empty_heap() const { return heap_.empty(); }

  /// The worst entry of the heap, taken out. It may be stale: the caller
  /// checks that the slot is `queued_at` and holds a cell of the same score.
  Worst_cell_entry pop()
  {
    const Worst_cell_entry e = heap_.top();
    heap_.pop();
    return e;
  }

  bool queued_at(std::size_t slot) const { return slot < state_.size() && state_[slot] == queued; }

  /// With the heap empty, raises the bound so that about a batch of the
  /// cells waiting outside it score below, and moves those in.
  /// `score_of(slot)` gives the score of the cell in `slot` (a
  /// `std::optional<float>`), or nothing when the slot holds no cell that may
  /// wait any more: the slot then waits no more. False when no cell waits.
  template <class ScoreOf>
  bool refill(ScoreOf score_of)
  {
    if(deferred_cells_ == 0) return false;
    bound_ = next_bound();
    sample_.clear();
    offered_ = 0;
    stride_ = 1;
    // The slots in order: one byte each to read, and only the waiting cells measured.
    for(std::size_t slot = 0; slot < state_.size(); ++slot)
    {
      if(state_[slot] != deferred) continue;
      const auto s = score_of(slot);
      if(!s)
      {
        state_[slot] = idle;
        --deferred_cells_;
      }
      else if(!(*s >= bound_))
      {
        state_[slot] = queued;
        --deferred_cells_;
        heap_.push(Worst_cell_entry{*s, std::uint32_t(slot)});
      }
      else
        offer(*s);
    }
    return !heap_.empty() || deferred_cells_ > 0;
  }

private:
  static constexpr std::uint8_t idle = 0, queued = 1, deferred = 2, settled = 3;
  static constexpr std::size_t sample_size = 1024;

  void leave(std::size_t slot)
  {
    if(state_[slot] == deferred) --deferred_cells_;
  }

  // Every `stride_`-th score offered is kept; when the sample holds twice
  // its size, every other one is dropped and the stride doubles.
  void offer(float s)
  {
    if(std::isnan(s) || offered_++ % stride_ != 0) return;
    sample_.push_back(s);
    if(sample_.size() < 2 * sample_size) return;
    for(std::size_t k = 0; 2 * k < sample_.size(); ++k) sample_[k] = sample_[2 * k];
    sample_.resize(sample_.size() / 2);
    stride_ *= 2;
  }

  // Just above the score below which a batch of the sampled cells lies: the
  // cells of that score come in, so each refill takes some. With a sample
  // smaller than a batch, or one the cells outside have outgrown, every
  // cell comes in.
  float next_bound()
  {
    if(offered_ <= batch_ || sample_.empty()) return std::numeric_limits<float>::infinity();
    const std::size_t k = std::size_t(double(sample_.size()) * double(batch_) / double(offered_));
    std::nth_element(sample_.begin(), sample_.begin() + std::ptrdiff_t(k), sample_.end());
    // The cells outside the heap scored at least the bound when they left it.
    return std::nextafter((std::max)(sample_[k], bound_), std::numeric_limits<float>::infinity());
  }

  std::size_t batch_;
  float bound_ = -std::numeric_limits<float>::infinity();
  std::vector<std::uint8_t> state_;
  // On a deque, the heap grows by pieces: a vector would hold its old and
  // new arrays at once when it doubles.
  std::priority_queue<Worst_cell_entry, std::deque<Worst_cell_entry>> heap_;
  std::vector<float> sample_;
  std::size_t offered_ = 0, stride_ = 1;
  std::size_t deferred_cells_ = 0; // cells waiting outside the heap
};

} // namespace internal
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_INTERNAL_WORST_CELL_QUEUE_H
