// SPDX-License-Identifier: GPL-3.0-or-later
// Deterministic mutation testing of the laboratory's readers, as the
// package's readers are tested (test/Edge_swapping_3/test_reader_mutations.cpp):
// each seed file of laboratory/test/fuzz/corpus is mutated a few thousand
// times, from a seed that a failure prints (EDGE_SWAPPING_3_MUTATION_SEED and
// EDGE_SWAPPING_3_MUTATIONS override the seed and the count). Each mutant is
// accepted or rejected with a message that names the file; an exception of
// another kind, a crash or a hang fails. Mutants also go through the program:
// exit 0 or 2 (fuzz/mutation.h).

#include "test_common.h"
#include "program_runner.h"
#include "fuzz/laboratory_reader_harness.h"
#include "fuzz/mutation.h"
#include <filesystem>

using namespace test;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> seed_files(lab_fuzz::Reader reader)
{
  const auto texts = fuzz::seed_files(fs::path(EDGE_SWAPPING_3_LABORATORY_FIXTURES).parent_path() / "fuzz" / "corpus" /
                                      lab_fuzz::reader_name(reader));
  REQUIRE(!texts.empty());
  return texts;
}

} // namespace

TEST_CASE("Every laboratory reader accepts a valid input or rejects it with a message naming the file - under mutation",
          "[mutation]")
{
  for(lab_fuzz::Reader reader : {lab_fuzz::Reader::topcom, lab_fuzz::Reader::case_json, lab_fuzz::Reader::results,
                                 lab_fuzz::Reader::streamed, lab_fuzz::Reader::trace})
    fuzz::require_accepted_or_named(lab_fuzz::reader_name(reader), seed_files(reader), [reader](const std::string& text) {
      const lab_fuzz::Outcome o = lab_fuzz::run(reader, text);
      return std::make_pair(o.accepted, o.message);
    }, {"fuzz.", "TOPCOM output"});
}

TEST_CASE("The laboratory's program on mutated files: exit 0 or 2 - and on 2 no shrunk case", "[mutation][program]")
{
  Workdir w;
  // A results file is its own output (appended to); a shrunk case is written or not at all.
  fuzz::require_program_exits_cleanly(w, seed_files(lab_fuzz::Reader::case_json), "in.json",
                                      "shrink IN -o OUT.json --expect stuck", "edge_swap_lab: error: ", true);
  fuzz::require_program_exits_cleanly(w, seed_files(lab_fuzz::Reader::results), "in.jsonl",
                                      "experiment --families random-cube --sizes 6 --seeds 1 -o IN",
                                      "edge_swap_lab: error: ", false);
  fuzz::require_program_exits_cleanly(
      w, seed_files(lab_fuzz::Reader::streamed), "in.jsonl",
      "experiment --families cube-corners --sizes 8 --seeds 1 --starts topcom --stream --stream-batch 20 "
      "--strategies plain,helper --orders storage,priority --threads 1 "
      "--readings \"until-destroyed,pass-over,no-swap-no-tag;never-cleared,any-tetrahedron,no-swap\" -o IN",
      "edge_swap_lab: error: ", false);
}
