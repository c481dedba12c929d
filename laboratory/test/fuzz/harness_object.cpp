// SPDX-License-Identifier: GPL-3.0-or-later
// The harness of every laboratory reader compiled once, for all its libFuzzer targets.

#include "laboratory_reader_harness.h"

namespace lab_fuzz {

Outcome run_compiled(Reader reader, std::string_view data) { return run(reader, data); }

} // namespace lab_fuzz
