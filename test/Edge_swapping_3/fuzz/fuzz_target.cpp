// SPDX-License-Identifier: GPL-3.0-or-later
// A libFuzzer target for one reader of the package, chosen at compile time
// by EDGE_SWAPPING_3_FUZZ_READER (node, ele, medit, msh, vtu); the harness
// itself is compiled once (harness_object.cpp).
// Built by -DEDGE_SWAPPING_3_FUZZ=ON with clang; run by scripts/fuzz.sh. A
// rejection is fine; an exception other than a reader's error, a crash, a
// sanitizer report or a time-out is a finding.

#include <cstddef>
#include <cstdint>
#include <string_view>
#include "readers.h"

#ifndef EDGE_SWAPPING_3_FUZZ_READER
#error "EDGE_SWAPPING_3_FUZZ_READER names the reader (node, ele, medit, msh, vtu)"
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  fuzz::run_compiled(fuzz::Reader::EDGE_SWAPPING_3_FUZZ_READER,
                     std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
