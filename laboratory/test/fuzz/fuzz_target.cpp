// SPDX-License-Identifier: GPL-3.0-or-later
// A libFuzzer target for one of the laboratory's readers, chosen at compile
// time by EDGE_SWAPPING_3_FUZZ_READER (topcom, case_json, results, streamed,
// trace). Built by -DEDGE_SWAPPING_3_FUZZ=ON with clang; run by scripts/fuzz.sh.

#include "laboratory_readers.h"
#include <cstddef>
#include <cstdint>
#include <string_view>

#ifndef EDGE_SWAPPING_3_FUZZ_READER
#error "EDGE_SWAPPING_3_FUZZ_READER names the reader (topcom, case_json, results, streamed, trace)"
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  lab_fuzz::run_compiled(lab_fuzz::Reader::EDGE_SWAPPING_3_FUZZ_READER,
                         std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
