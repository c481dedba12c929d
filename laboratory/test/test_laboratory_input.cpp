// SPDX-License-Identifier: GPL-3.0-or-later
// Hostile input to the laboratory: its files (cases, results, TOPCOM's
// output) and its program's options. Bad input means exit 2, a message that
// names the file or the option and the problem, and no output file.

#include "test_common.h"
#include "program_runner.h"
#include <CGAL/Edge_swapping_3/Laboratory/IO/conjecture_json.h>
#include <CGAL/Edge_swapping_3/Laboratory/IO/topcom_runner.h>
#include <CGAL/Edge_swapping_3/Laboratory/IO/topcom.h>
#include <CGAL/Edge_swapping_3/Laboratory/Conjecture_case.h>
#include <sys/wait.h>
#include <csignal>
#include <fstream>
#include <sstream>

using namespace test;
namespace IO = CGAL::Edge_swapping_3::IO;
namespace fs = std::filesystem;

namespace {

std::string case_text(const std::string& extra)
{
  return "{\"points\": [[0,0,0],[1,0,0],[0,1,0],[0,0,1],[1,1,1]], \"strategy\": \"plain\", \"order\": \"random\", "
         "\"seed\": 1" + extra + "}";
}

} // namespace

TEST_CASE("Cell indices out of range are errors in case files and in TOPCOM's output", "[hostile]")
{
  // From case files (replay and shrink): -1, a point that does not exist, not four.
  Workdir w;
  for(const std::string cells : {"[[0,1,2,3],[1,2,3,-1]]", "[[0,1,2,3],[1,2,3,5]]", "[[0,1,2]]", "[[0,1,2,\"3\"]]", "7"})
  {
    w.write("case.json", case_text(", \"start\": \"cells\", \"cells\": " + cells));
    require_clean_rejection(w, "replay " + w.path("case.json"), "case.json: bad case file: ", {"case.json"});
    require_clean_rejection(w, "shrink " + w.path("case.json") + " -o " + w.path("s.json"), "case.json: bad case file: ",
                    {"case.json"});
  }

  // From TOPCOM's output: a sign or a number too large is not an index.
  for(const std::string bad : {"T[0] := {{0,1,2,-1}};", "T[0] := {{0,1,2,+3}};", "T[0] := {{0,1,2,99999999999999999999999}};"})
  {
    INFO(bad);
    std::istringstream in(bad + "\n");
    REQUIRE_THROWS_WITH(IO::read_topcom_triangulations(in), Catch::Contains("TOPCOM output line 1: bad index"));
  }
}

TEST_CASE("Defect 4: a results file is checked, line by line, before anything is appended", "[hostile]")
{
  Workdir w;
  const std::string args = "experiment --families random-cube --sizes 8 --seeds 1 -o " + w.path("r.jsonl");
  REQUIRE(w.run(args).exit_code == 0);
  const std::string good = Workdir::slurp(w.path("r.jsonl"));
  auto first_line = nlohmann::json::parse(good.substr(0, good.find('\n')));
  REQUIRE(IO::results_line_problem(first_line).empty());
  auto without = first_line;
  without.erase("start");
  auto wrong = first_line;
  wrong["cycles"] = "many";
  auto negative = first_line;
  negative["seed"] = -1;
  for(const auto& [line, what] : std::vector<std::pair<std::string, std::string>>{
          {without.dump(), "r.jsonl:2: not a results line: \"start\" is missing or not a string"},
          {wrong.dump(), "r.jsonl:2: not a results line: \"cycles\" is missing or not a number"},
          {negative.dump(), "r.jsonl:2: not a results line: \"seed\" is missing or not a whole number"},
          {"[1, 2]", "r.jsonl:2: not a results line: not a JSON object"},
          {"{\"key\": ", "r.jsonl:2: not a JSON line"}})
  {
    const std::string text = good.substr(0, good.find('\n') + 1) + line + "\n";
    w.write("r.jsonl", text);
    const Run r = w.run(args.substr(0, args.find("--seeds")) + "--seeds 1-2 -o " + w.path("r.jsonl"));
    INFO(line << "\nstderr: " << r.err);
    REQUIRE(r.exit_code == 2);
    REQUIRE(r.err.find(what) != std::string::npos);
    REQUIRE(Workdir::slurp(w.path("r.jsonl")) == text); // nothing appended, nothing cut
  }
}

TEST_CASE("Defect 5: built-in families go through the point-set checks", "[hostile]")
{
  Workdir w;
  for(const std::string size : {"0", "1", "2", "3"})
    require_clean_rejection(w, "experiment --families random-cube --sizes " + size + " -o " + w.path("r.jsonl"),
                    "--sizes: " + size + " points; a size is from 4", {});
  require_clean_rejection(w, "experiment --sizes 200000000 -o " + w.path("r.jsonl"), "a size is from 4 to 100000000", {});
  require_clean_rejection(w, "experiment --families random-integer --sizes 100 --starts topcom -o " + w.path("r.jsonl"),
                  "--starts topcom takes at most 20 points", {});
  // Integer points of one sphere: the sphere for many more than 20,000 would not be found.
  require_clean_rejection(w, "experiment --families cospherical --sizes 20001 -o " + w.path("r.jsonl"),
                          "cospherical: at most 20000 points (the integer points of one sphere), not 20001", {});
  require_clean_rejection(w, "experiment --families two-spheres --sizes 1000000 -o " + w.path("r.jsonl"),
                          "two-spheres: at most 40000 points (those of two spheres), not 1000000", {});
  // The same checks in the runner itself, whatever calls it.
  ES::Conjecture_case<Point> c;
  c.points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)};
  REQUIRE_THROWS_WITH(ES::run_conjecture_case(c), Catch::Contains("fewer than four points"));
  c.points.push_back(Point(1, 1, 0));
  REQUIRE_THROWS_WITH(ES::run_conjecture_case(c), Catch::Contains("coplanar"));
}

namespace {

// Runs `body` in a child process whose temporary folder is `tmp`; returns
// its wait status. The child ends with _exit: no Catch2 state is torn down twice.
template <class Body>
int in_child_with_tmpdir(const std::string& tmp, Body body)
{
  fs::create_directories(tmp);
  const pid_t child = ::fork();
  if(child == 0)
  {
    ::setenv("TMPDIR", tmp.c_str(), 1);
    int code = 3;
    try
    {
      code = body();
    }
    catch(...)
    {
    }
    ::_exit(code);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  return status;
}

std::vector<std::string> files_in(const std::string& dir)
{
  std::vector<std::string> names;
  for(const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  return names;
}

} // namespace

TEST_CASE("TOPCOM's input file is not left behind when the input is refused or the process killed", "[hostile]")
{
  Workdir w;
  const std::string tmp = w.path("tmp");
  const std::vector<Point> cube = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(1, 1, 0),
                                   Point(0, 0, 1), Point(1, 0, 1), Point(0, 1, 1), Point(1, 1, 1)};
  SECTION("a point TOPCOM cannot take (not an integer) is refused before any file is made")
  {
    const int status = in_child_with_tmpdir(tmp, [] {
      const std::vector<Point> points = {Point(0.5, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)};
      try
      {
        IO::topcom_triangulations(points, 10);
      }
      catch(const std::invalid_argument&)
      {
        return 0;
      }
      return 1;
    });
    REQUIRE(WIFEXITED(status));
    REQUIRE(WEXITSTATUS(status) == 0);
  }
  SECTION("a process killed while TOPCOM runs leaves no file (it used to leave one)")
  {
    const int status = in_child_with_tmpdir(tmp, [&] {
      IO::for_each_topcom_triangulation(cube, 1000, [](std::size_t, const std::vector<std::array<std::size_t, 4>>&) {
        ::raise(SIGKILL);
        return true;
      });
      return 1;
    });
    REQUIRE(WIFSIGNALED(status));
    REQUIRE(WTERMSIG(status) == SIGKILL);
  }
  SECTION("a whole enumeration: the 74 fine triangulations of the cube")
  {
    const int status = in_child_with_tmpdir(tmp, [&] {
      const auto result = IO::topcom_triangulations(cube, 1000);
      return result.triangulations.size() == 74 && !result.truncated ? 0 : 1;
    });
    REQUIRE(WIFEXITED(status));
    REQUIRE(WEXITSTATUS(status) == 0);
  }
  INFO("left in the temporary folder: " << files_in(tmp).size());
  REQUIRE(files_in(tmp).empty());
}

TEST_CASE("Defect 6: threads that cannot start are not fatal", "[hostile]")
{
  // 150 MB of address space leaves room for a few 8 MB thread stacks, not 64:
  // TBB runs the instances on the threads it could start.
  // Under AddressSanitizer (scripts/sanitize_tests.sh) no program starts in 150 MB.
  if(std::getenv("EDGE_SWAPPING_3_SANITIZED"))
  {
    WARN("skipped under the sanitizers: the address space limit leaves no room for ASan's shadow memory");
    return;
  }
  Workdir w;
  const Run r = w.run_with("ulimit -v 150000;", "experiment --families random-cube --sizes 10 --seeds 1-4 --threads 64 -o " +
                                                   w.path("s.jsonl"));
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.out.find("8 instances in") != std::string::npos);
  REQUIRE(Workdir::slurp(w.path("s.jsonl")).size() > 0);
  require_clean_rejection(w, "experiment --threads 100000 -o " + w.path("t.jsonl"), "--threads is at most 256", {"s.jsonl"});
}

TEST_CASE("A folder is not an output file", "[hostile]")
{
  Workdir w;
  fs::create_directories(w.path("dir"));
  require_clean_rejection(w, "shrink " + w.path("missing.json") + " -o " + w.path("dir"), "is a directory", {"dir"});
  require_clean_rejection(w, "experiment -o " + w.path("dir"), "is a directory", {"dir"});
}

TEST_CASE("A full disk is an error - every write of a results file is checked", "[hostile]")
{
  // A file size limit of 512 bytes, with SIGXFSZ ignored: writes fail with EFBIG, as on a full disk.
  Workdir w;
  const std::string limit = "trap '' XFSZ; ulimit -f 1;";
  Run r = w.run_with(limit, "experiment --families random-cube --sizes 10 --seeds 1-100 -o " + w.path("full.jsonl"));
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 2);
  REQUIRE(r.err.find("cannot write '" + w.path("full.jsonl") + "': File too large") != std::string::npos);
  // Every whole line that was written is a result; a cut last line is dropped on resume.
  REQUIRE(IO::read_results_file(w.path("full.jsonl"), false).size() >= 1);
  REQUIRE(w.outputs({"full.jsonl"}) == 0); // no partial file left
}

TEST_CASE("A case whose points span more than the supported extent is refused", "[hostile]")
{
  Workdir w;
  w.write("c.json", "{\"points\": [[0,0,0],[1e307,0,0],[0,1,0],[0,0,1]], \"start\": \"placing\", \"strategy\": \"plain\", "
                    "\"order\": \"random\", \"seed\": 1}");
  require_clean_rejection(w, "replay " + w.path("c.json"), "the points span 1e+307 along x", {"c.json"});
}

TEST_CASE("Every message of the laboratory's program names the option or the file", "[hostile]")
{
  Workdir w;
  fs::create_directories(w.path("d.node"));
  fs::create_directories(w.path("d.json"));
  w.write("x.json", case_text(", \"start\": \"scramble:x\""));
  w.write("y.json", case_text(", \"start\": \"scramble:99999999999999999999\""));
  const std::vector<std::string> inputs = {"d.node", "d.json", "x.json", "y.json"};
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"experiment --starts scramble:1e5 -o " + w.path("r.jsonl"), "--starts scramble:K needs a whole number"},
      {"experiment --seeds 1-99999999999 -o " + w.path("r.jsonl"), "--seeds is 99999999999"},
      {"experiment --shard x/2 -o " + w.path("r.jsonl"), "--shard I/N needs a whole number"},
      {"replay " + w.path("x.json"), "x.json: bad case file: start scramble:K needs a whole number, not 'x'"},
      {"replay " + w.path("y.json"), "y.json: bad case file: start scramble:K is 99999999999999999999"},
      {"replay " + w.path("d.json"), "d.json: is a directory"},
      {"shrink " + w.path("d.json") + " -o " + w.path("s.json"), "d.json: is a directory"},
      {"experiment --points-file " + w.path("d.node") + " -o " + w.path("r.jsonl"), "d.node: is a directory"},
  };
  for(const auto& [args, what] : cases) require_clean_rejection(w, args, what, inputs);
}
