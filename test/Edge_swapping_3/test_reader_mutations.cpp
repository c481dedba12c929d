// SPDX-License-Identifier: GPL-3.0-or-later
// Deterministic mutation testing of every reader (the CI-sized cousin of
// scripts/fuzz.sh): each seed file of test/Edge_swapping_3/fuzz/corpus is
// mutated a few thousand times, from a seed that a failure prints
// (EDGE_SWAPPING_3_MUTATION_SEED and EDGE_SWAPPING_3_MUTATIONS override the
// seed and the count). Each mutant is either accepted (a valid mesh) or
// rejected with a message that names the file; an
// exception of another kind, a crash or a hang fails. A few hundred mutants
// also go through the program: exit 0 or 2, and on 2 no output file.

#include "test_common.h"
#include "program_runner.h"
#include "fuzz/reader_harness.h"
#include "fuzz/mutation.h"
#include <filesystem>

using namespace test;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> seed_files(fuzz::Reader reader)
{
  const auto texts = fuzz::seed_files(fs::path(EDGE_SWAPPING_3_FIXTURES).parent_path() / "fuzz" / "corpus" /
                                      fuzz::reader_name(reader));
  REQUIRE(!texts.empty());
  return texts;
}

} // namespace

TEST_CASE("Every reader accepts a valid input or rejects it with a message naming the file - under mutation", "[mutation]")
{
  for(fuzz::Reader reader : {fuzz::Reader::node, fuzz::Reader::ele, fuzz::Reader::medit, fuzz::Reader::msh,
                             fuzz::Reader::vtu})
    fuzz::require_accepted_or_named(fuzz::reader_name(reader), seed_files(reader), [reader](const std::string& text) {
      const fuzz::Outcome o = fuzz::run(reader, text);
      return std::make_pair(o.accepted, o.message);
    }, {"fuzz."});
}

TEST_CASE("The program on mutated files: exit 0 or 2 - and on 2 no output file", "[mutation][program]")
{
  Workdir w;
  struct Run_kind { fuzz::Reader reader; std::string input, args; };
  for(const Run_kind& kind : std::vector<Run_kind>{
          {fuzz::Reader::node, "in.node", "optimize IN -o OUT.ele --stats OUT.json"},
          {fuzz::Reader::medit, "in.mesh", "optimize IN -o OUT.mesh"},
          {fuzz::Reader::msh, "in.msh", "optimize IN --criterion minmax-dihedral --operations topological -o OUT.msh"},
          {fuzz::Reader::vtu, "in.vtu", "refine IN --by aspect-ratio --target 2 --max-sites 20 -o OUT.vtu"}})
    fuzz::require_program_exits_cleanly(w, seed_files(kind.reader), kind.input, kind.args, "edge_swap: error: ", true);
}
