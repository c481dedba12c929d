// SPDX-License-Identifier: GPL-3.0-or-later
// Ctrl-C during a long optimization: the first SIGINT asks the driver to end
// after the operation under way, so the mesh so far is written; a second
// one ends the program at once (the output files are written whole or not
// at all, so none is left half written).

#ifndef EDGE_SWAP_INTERRUPTION_H
#define EDGE_SWAP_INTERRUPTION_H

#include <atomic>
#include <csignal>

namespace edge_swap {

/// Set by the first SIGINT while an `Interruption_scope` lives.
inline std::atomic<bool> interruption_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the signal handler sets the flag");

extern "C" inline void request_interruption(int)
{
  interruption_requested.store(true);
  std::signal(SIGINT, SIG_DFL); // a second Ctrl-C ends the program
}

/// While it lives, SIGINT sets `interruption_requested` instead of ending the
/// program. A program started with SIGINT ignored (`nohup`, a background job
/// of a script) keeps ignoring it.
class Interruption_scope
{
public:
  Interruption_scope()
  {
    interruption_requested.store(false);
    previous_ = std::signal(SIGINT, &request_interruption);
    if(previous_ == SIG_IGN) std::signal(SIGINT, SIG_IGN);
  }
  ~Interruption_scope() { std::signal(SIGINT, previous_ == SIG_ERR ? SIG_DFL : previous_); }
  Interruption_scope(const Interruption_scope&) = delete;
  Interruption_scope& operator=(const Interruption_scope&) = delete;

  const std::atomic<bool>* flag() const { return &interruption_requested; }

private:
  void (*previous_)(int);
};

} // namespace edge_swap

#endif // EDGE_SWAP_INTERRUPTION_H
