// SPDX-License-Identifier: GPL-3.0-or-later
// The laboratory's readers that are fuzzed (TOPCOM's output, cases, results,
// streamed results, traces), and what a harness run says: light enough for
// the libFuzzer targets' own translation units.

#ifndef EDGE_SWAPPING_3_LABORATORY_FUZZ_READERS_H
#define EDGE_SWAPPING_3_LABORATORY_FUZZ_READERS_H

#include <string>
#include <string_view>

namespace lab_fuzz {

struct Outcome
{
  bool accepted = false;
  std::string message; ///< the error, when rejected
};

enum class Reader { topcom, case_json, results, streamed, trace };

inline const char* reader_name(Reader r)
{
  switch(r)
  {
  case Reader::topcom: return "topcom";
  case Reader::case_json: return "case_json";
  case Reader::streamed: return "streamed";
  case Reader::trace: return "trace";
  default: return "results";
  }
}

/// The file name the harness gives `reader`'s input in messages.
inline std::string file_name(Reader r)
{
  switch(r)
  {
  case Reader::topcom: return "TOPCOM output";
  case Reader::case_json: return "fuzz.json";
  case Reader::streamed: return "fuzz.stream.jsonl";
  case Reader::trace: return "fuzz.trace.jsonl";
  default: return "fuzz.jsonl";
  }
}

/// Runs the harness of `reader` on `data` (compiled once, in harness_object.cpp).
Outcome run_compiled(Reader reader, std::string_view data);

} // namespace lab_fuzz

#endif
