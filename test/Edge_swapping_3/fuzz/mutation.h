// SPDX-License-Identifier: GPL-3.0-or-later
// The mutation tests of the suite (the CI-sized cousins of scripts/fuzz.sh):
// seed files edited from a seed that a failure prints
// (EDGE_SWAPPING_3_MUTATION_SEED and EDGE_SWAPPING_3_MUTATIONS override the
// seed and the count), through a reader's harness or through the program.

#ifndef EDGE_SWAPPING_3_FUZZ_MUTATION_H
#define EDGE_SWAPPING_3_FUZZ_MUTATION_H

#include "../program_runner.h"
#include <CGAL/Random.h>
#include <catch2/catch.hpp>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <tuple>
#include <vector>

namespace fuzz {

/// The texts of the seed files in `dir`, in name order (the same everywhere:
/// a mutation seed reproduces).
inline std::vector<std::string> seed_files(const std::filesystem::path& dir)
{
  std::vector<std::string> texts;
  std::vector<std::filesystem::path> paths;
  for(const auto& e : std::filesystem::directory_iterator(dir)) paths.push_back(e.path());
  std::sort(paths.begin(), paths.end()); // the same order everywhere: the seed reproduces
  for(const auto& p : paths)
  {
    std::ifstream in(p, std::ios::binary);
    texts.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return texts;
}

/// The environment variable `name` as a number, or `fallback`.
inline unsigned long environment_number(const char* name, unsigned long fallback)
{
  const char* v = std::getenv(name);
  return v ? std::strtoul(v, nullptr, 10) : fallback;
}

// One to four edits of the kinds that broke readers before: bit flips, odd
// bytes, cut and copied ranges, swapped lines, and numbers replaced by the
// values that overflow, wrap, underflow or are not numbers.
inline std::string mutate(std::string s, CGAL::Random& r)
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

/// Requires of `run` (a text to an outcome with `accepted` and `message`) that
/// it accepts each seed of `reader`, and accepts each mutant or rejects it
/// with a message that starts with one of `names` and names a place (": ");
/// another exception fails. Both outcomes must occur.
template <class Run>
void require_accepted_or_named(const std::string& reader, const std::vector<std::string>& seeds, Run run,
                               const std::vector<std::string>& names)
{
  const unsigned long seed = environment_number("EDGE_SWAPPING_3_MUTATION_SEED", 20261126);
  const unsigned long count = environment_number("EDGE_SWAPPING_3_MUTATIONS", 3000);
  std::size_t accepted = 0, rejected = 0;
  for(unsigned long k = 0; k < count; ++k)
  {
    CGAL::Random r(unsigned(seed + k));
    const std::string& original = seeds[k % seeds.size()];
    const std::string text = k < seeds.size() ? original : mutate(original, r);
    INFO("reader " << reader << ", EDGE_SWAPPING_3_MUTATION_SEED=" << seed << ", mutant " << k << " (seed " << seed + k
                   << ")\n" << text.substr(0, 2000));
    bool ok = false;
    std::string message;
    REQUIRE_NOTHROW(std::tie(ok, message) = run(text));
    if(k < seeds.size()) REQUIRE(ok); // the seeds themselves are valid
    if(ok) { ++accepted; continue; }
    ++rejected;
    INFO("message: " << message);
    REQUIRE(std::any_of(names.begin(), names.end(), [&](const std::string& n) { return message.rfind(n, 0) == 0; }));
    REQUIRE(message.find(": ") != std::string::npos);
  }
  // Both outcomes occur: the mutants reach past the first line.
  std::cout << "mutation test, reader " << reader << ", seed " << seed << ": " << accepted << " accepted, " << rejected
            << " rejected\n";
  REQUIRE(accepted >= seeds.size());
  REQUIRE(rejected > count / 4);
}

/// Runs the program under test with `args` on 40 mutants of `seeds`, each
/// written as `input` in `w` (IN in `args` is its path, OUT that of an
/// output): exit 0 or 2; on 2 the message starts with `error_start` and, with
/// `no_output_on_error`, no file is left but the input.
inline void require_program_exits_cleanly(const test::Workdir& w, const std::vector<std::string>& seeds,
                                          const std::string& input, const std::string& args,
                                          const std::string& error_start, bool no_output_on_error)
{
  namespace fs = std::filesystem;
  const unsigned long seed = environment_number("EDGE_SWAPPING_3_MUTATION_SEED", 20261126);
  for(unsigned long k = 0; k < 40; ++k)
  {
    CGAL::Random r(unsigned(seed + k));
    const std::string text = mutate(seeds[k % seeds.size()], r);
    w.write(input, text);
    std::string line = args;
    line.replace(line.find("IN"), 2, w.path(input));
    for(auto out = line.find("OUT"); out != std::string::npos; out = line.find("OUT")) line.replace(out, 3, w.path("out"));
    const test::Run run = w.run(line);
    INFO(line << "\nEDGE_SWAPPING_3_MUTATION_SEED=" << seed << ", mutant " << k << "\n" << text.substr(0, 2000)
              << "\nstderr: " << run.err);
    REQUIRE((run.exit_code == 0 || run.exit_code == 2));
    if(run.exit_code == 2)
    {
      REQUIRE(run.err.find(error_start) == 0);
      if(no_output_on_error) REQUIRE(w.outputs({input}) == 0);
    }
    for(const auto& e : fs::directory_iterator(w.path("")))
      if(e.path().filename() != "stdout" && e.path().filename() != "stderr") fs::remove(e.path());
  }
}

} // namespace fuzz

#endif
