// SPDX-License-Identifier: GPL-3.0-or-later
// The readers that are fuzzed, and what a harness run says: light enough for
// the libFuzzer targets' own translation units (reader_harness.h runs them).

#ifndef EDGE_SWAPPING_3_FUZZ_READERS_H
#define EDGE_SWAPPING_3_FUZZ_READERS_H

#include <string>
#include <string_view>

namespace fuzz {

struct Outcome
{
  bool accepted = false;
  std::string message; ///< the error, when rejected
};

enum class Reader { node, ele, medit, msh, vtu };

inline const char* reader_name(Reader r)
{
  switch(r)
  {
  case Reader::node: return "node";
  case Reader::ele: return "ele";
  case Reader::medit: return "medit";
  case Reader::msh: return "msh";
  default: return "vtu";
  }
}

/// The file name the harness gives `reader`'s input in messages.
inline std::string file_name(Reader r)
{
  switch(r)
  {
  case Reader::node: return "fuzz.node";
  case Reader::ele: return "fuzz.ele";
  case Reader::medit: return "fuzz.mesh";
  case Reader::msh: return "fuzz.msh";
  default: return "fuzz.vtu";
  }
}

/// Runs the harness of `reader` on `data` (compiled once, in harness_object.cpp).
Outcome run_compiled(Reader reader, std::string_view data);

} // namespace fuzz

#endif
