// SPDX-License-Identifier: GPL-3.0-or-later
// Deterministic mutation testing of every reader (the CI-sized cousin of
// scripts/fuzz.sh): each seed file of test/Edge_swapping_3/fuzz/corpus is
// mutated a few thousand times, from a seed that a failure prints
// (EDGE_SWAPPING_3_MUTATION_SEED and EDGE_SWAPPING_3_MUTATIONS override the
// seed and the count). Each mutant is either accepted (a valid mesh, case or
// results file) or rejected with a message that names the file; an
// exception of another kind, a crash or a hang fails. A few hundred mutants
// also go through the program: exit 0 or 2, and on 2 no output file.

#include "test_common.h"
#include "program_runner.h"
#include "fuzz/reader_harness.h"
#include <CGAL/Random.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>

using namespace test;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> seed_files(fuzz::Reader reader)
{
  std::vector<std::string> texts;
  const fs::path dir = fs::path(EDGE_SWAPPING_3_FIXTURES).parent_path() / "fuzz" / "corpus" / fuzz::reader_name(reader);
  std::vector<fs::path> paths;
  for(const auto& e : fs::directory_iterator(dir)) paths.push_back(e.path());
  std::sort(paths.begin(), paths.end()); // the same order everywhere: the seed reproduces
  for(const auto& p : paths) texts.push_back(Workdir::slurp(p.string()));
  REQUIRE(!texts.empty());
  return texts;
}

unsigned long environment_number(const char* name, unsigned long fallback)
{
  const char* v = std::getenv(name);
  return v ? std::strtoul(v, nullptr, 10) : fallback;
}

// One to four edits of the kinds that broke readers before: bit flips, odd
// bytes, cut and copied ranges, swapped lines, and numbers replaced by the
// values that overflow, wrap, underflow or are not numbers.
std::string mutate(std::string s, CGAL::Random& r)
{
  static const std::vector<std::string> numbers = {
      "-1", "0", "1", "4", "-0", "3.5", "1e30", "1e308", "1e-320", "1e400", "nan", "inf", "-inf", "2147483648",
      "4294967296", "9223372036854775807", "18446744073709551616", "99999999999999999999", "6148914691236517206", "1e", "+", "0x10"};
  static const std::string odd = std::string("\0\n \t#-.e9{}[]<>\"',:/=", 22);
  const int edits = r.get_int(1, 5);
  for(int e = 0; e < edits; ++e)
  {
    const std::size_t n = s.size();
    const std::size_t at = n ? std::size_t(r.get_int(0, int(n))) : 0;
    switch(r.get_int(0, 8))
    {
    case 0: if(n) s[at] = char(s[at] ^ (1 << r.get_int(0, 8))); break;
    case 1: if(n) s[at] = odd[std::size_t(r.get_int(0, int(odd.size())))]; break;
    case 2: s.erase(at, std::size_t(r.get_int(1, 17))); break;
    case 3: { const std::size_t from = n ? std::size_t(r.get_int(0, int(n))) : 0;
              s.insert(at, s.substr(from, std::size_t(r.get_int(1, 65)))); break; }
    case 4: case 5:
    {
      // Replace the number that starts at or after `at`.
      const std::size_t b = s.find_first_of("-0123456789", at);
      if(b == std::string::npos) break;
      const std::size_t end = s.find_first_not_of("-+0123456789.eE", b);
      s.replace(b, (end == std::string::npos ? s.size() : end) - b, numbers[std::size_t(r.get_int(0, int(numbers.size())))]);
      break;
    }
    case 6: s.resize(at); break;
    default:
    {
      // Swap the line at `at` with another.
      const std::size_t a0 = s.rfind('\n', at) == std::string::npos ? 0 : s.rfind('\n', at) + 1;
      const std::size_t a1 = s.find('\n', a0);
      const std::size_t b0 = n ? std::size_t(r.get_int(0, int(n))) : 0;
      const std::size_t c0 = s.rfind('\n', b0) == std::string::npos ? 0 : s.rfind('\n', b0) + 1;
      const std::size_t c1 = s.find('\n', c0);
      if(a1 == std::string::npos || c1 == std::string::npos || a0 == c0) break;
      const std::string line_a = s.substr(a0, a1 - a0), line_c = s.substr(c0, c1 - c0);
      if(a0 < c0) { s.replace(c0, c1 - c0, line_a); s.replace(a0, a1 - a0, line_c); }
      else { s.replace(a0, a1 - a0, line_c); s.replace(c0, c1 - c0, line_a); }
    }
    }
  }
  return s;
}

} // namespace

TEST_CASE("Every reader accepts a valid input or rejects it with a message naming the file - under mutation", "[mutation]")
{
  const unsigned long seed = environment_number("EDGE_SWAPPING_3_MUTATION_SEED", 20261126);
  const unsigned long count = environment_number("EDGE_SWAPPING_3_MUTATIONS", 3000);
  for(fuzz::Reader reader : {fuzz::Reader::node, fuzz::Reader::ele, fuzz::Reader::medit, fuzz::Reader::msh,
                             fuzz::Reader::vtu, fuzz::Reader::topcom, fuzz::Reader::case_json, fuzz::Reader::results,
                             fuzz::Reader::streamed, fuzz::Reader::trace})
  {
    const auto seeds = seed_files(reader);
    std::size_t accepted = 0, rejected = 0;
    for(unsigned long k = 0; k < count; ++k)
    {
      CGAL::Random r(unsigned(seed + k));
      const std::string& original = seeds[k % seeds.size()];
      const std::string text = k < seeds.size() ? original : mutate(original, r);
      INFO("reader " << fuzz::reader_name(reader) << ", EDGE_SWAPPING_3_MUTATION_SEED=" << seed << ", mutant " << k
                     << " (seed " << seed + k << ")\n" << text.substr(0, 2000));
      fuzz::Outcome o;
      REQUIRE_NOTHROW(o = fuzz::run(reader, text));
      if(k < seeds.size()) REQUIRE(o.accepted); // the seeds themselves are valid
      if(o.accepted) { ++accepted; continue; }
      ++rejected;
      INFO("message: " << o.message);
      REQUIRE((o.message.rfind("fuzz.", 0) == 0 || o.message.rfind("TOPCOM output", 0) == 0));
      REQUIRE(o.message.find(": ") != std::string::npos);
    }
    // Both outcomes occur: the mutants reach past the first line.
    std::cout << "mutation test, reader " << fuzz::reader_name(reader) << ", seed " << seed << ": " << accepted
              << " accepted, " << rejected << " rejected\n";
    REQUIRE(accepted >= seeds.size());
    REQUIRE(rejected > count / 4);
  }
}

TEST_CASE("The program on mutated files: exit 0 or 2 - and on 2 no output file", "[mutation][program]")
{
  const unsigned long seed = environment_number("EDGE_SWAPPING_3_MUTATION_SEED", 20261126);
  Workdir w;
  struct Run_kind { fuzz::Reader reader; std::string input, args; };
  const std::vector<Run_kind> kinds = {
      {fuzz::Reader::node, "in.node", "optimize IN -o OUT.ele --stats OUT.json"},
      {fuzz::Reader::medit, "in.mesh", "optimize IN -o OUT.mesh"},
      {fuzz::Reader::msh, "in.msh", "optimize IN --criterion minmax-dihedral --operations topological -o OUT.msh"},
      {fuzz::Reader::vtu, "in.vtu", "refine IN --by aspect-ratio --target 2 --max-sites 20 -o OUT.vtu"},
      {fuzz::Reader::case_json, "in.json", "shrink IN -o OUT.json --expect stuck"},
      {fuzz::Reader::results, "in.jsonl", "experiment --families random-cube --sizes 6 --seeds 1 -o IN"},
      {fuzz::Reader::streamed, "in.jsonl",
       "experiment --families cube-corners --sizes 8 --seeds 1 --starts topcom --stream --stream-batch 20 "
       "--strategies plain,helper --orders storage,priority --threads 1 "
       "--readings \"until-destroyed,pass-over,no-swap-no-tag;never-cleared,any-tetrahedron,no-swap\" -o IN"}};
  for(const auto& kind : kinds)
  {
    const auto seeds = seed_files(kind.reader);
    for(unsigned long k = 0; k < 40; ++k)
    {
      CGAL::Random r(unsigned(seed + k));
      const std::string text = mutate(seeds[k % seeds.size()], r);
      w.write(kind.input, text);
      std::string args = kind.args;
      args.replace(args.find("IN"), 2, w.path(kind.input));
      const auto out = args.find("OUT");
      if(out != std::string::npos) args.replace(out, 3, w.path("out"));
      const auto out2 = args.find("OUT");
      if(out2 != std::string::npos) args.replace(out2, 3, w.path("out"));
      const Run run = w.run(args);
      INFO("edge_swap " << args << "\nEDGE_SWAPPING_3_MUTATION_SEED=" << seed << ", mutant " << k << "\n"
                        << text.substr(0, 2000) << "\nstderr: " << run.err);
      REQUIRE((run.exit_code == 0 || run.exit_code == 2));
      if(run.exit_code == 2)
      {
        REQUIRE(run.err.find("edge_swap: error: ") == 0);
        if(kind.reader != fuzz::Reader::results && kind.reader != fuzz::Reader::streamed)
          REQUIRE(w.outputs({kind.input}) == 0);
      }
      for(const auto& e : fs::directory_iterator(w.path("")))
        if(e.path().filename() != "stdout" && e.path().filename() != "stderr") fs::remove(e.path());
    }
  }
}
