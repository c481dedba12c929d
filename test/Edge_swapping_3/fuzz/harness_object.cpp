// SPDX-License-Identifier: GPL-3.0-or-later
// The harness of every reader compiled once, for all the libFuzzer targets.

#include "reader_harness.h"

namespace fuzz {

Outcome run_compiled(Reader reader, std::string_view data) { return run(reader, data); }

} // namespace fuzz
