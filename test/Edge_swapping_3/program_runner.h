// SPDX-License-Identifier: GPL-3.0-or-later
// Runs the program under test (EDGE_SWAP_BINARY: edge_swap, or the
// laboratory's edge_swap_lab) as a user would, in a scratch directory of its own.

#ifndef EDGE_SWAPPING_3_PROGRAM_RUNNER_H
#define EDGE_SWAPPING_3_PROGRAM_RUNNER_H

#include <catch2/catch.hpp>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace test {

namespace fs = std::filesystem;

struct Run
{
  int exit_code;
  std::string out, err;
};

class Workdir
{
public:
  Workdir()
  {
    static int counter = 0;
    dir_ = fs::temp_directory_path() / ("edge_swap_test_" + std::to_string(::getpid()) + "_" + std::to_string(++counter));
    fs::create_directories(dir_);
  }
  ~Workdir() { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  void write(const std::string& name, const std::string& text) const { std::ofstream(path(name)) << text; }

  static std::string slurp(const std::string& p)
  {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }

  Run run(const std::string& args) const { return run_with("", args); }

  /// Runs the program after the shell commands `prefix` (limits, traps).
  Run run_with(const std::string& prefix, const std::string& args) const
  {
    return run_program(prefix + " " + std::string(EDGE_SWAP_BINARY), args);
  }

  /// Runs `program` (a path, after shell commands if any) with `args`.
  Run run_program(const std::string& program, const std::string& args) const
  {
    const std::string cmd = "(" + program + " " + args + ") > " + path("stdout") + " 2> " + path("stderr");
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(path("stdout")), slurp(path("stderr"))};
  }

  /// Files in the directory other than the inputs and the captured streams.
  std::size_t outputs(const std::vector<std::string>& inputs) const
  {
    std::size_t n = 0;
    for(const auto& e : fs::directory_iterator(dir_))
    {
      const std::string name = e.path().filename().string();
      if(name == "stdout" || name == "stderr") continue;
      if(std::find(inputs.begin(), inputs.end(), name) == inputs.end()) ++n;
    }
    return n;
  }

private:
  fs::path dir_;
};

/// Runs the program with `args` and requires a clean rejection: exit 2, `what` in
/// the message, and no file in the directory but `inputs`.
inline void require_clean_rejection(const Workdir& w, const std::string& args, const std::string& what,
                                    const std::vector<std::string>& inputs)
{
  const Run r = w.run(args);
  INFO(EDGE_SWAP_BINARY << " " << args << "\nstderr: " << r.err);
  REQUIRE(r.exit_code == 2);
  REQUIRE(r.err.find(what) != std::string::npos);
  REQUIRE(w.outputs(inputs) == 0);
}

} // namespace test

#endif
