// SPDX-License-Identifier: GPL-3.0-or-later
// Runs TOPCOM (Debian's topcom package) on a point set and reads every fine
// triangulation it enumerates.

#ifndef EDGE_SWAP_TOPCOM_RUNNER_H
#define EDGE_SWAP_TOPCOM_RUNNER_H

#include "types.h"
#include <CGAL/Edge_swapping_3/IO/topcom.h>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <thread>
#include <unistd.h>

namespace edge_swap {

inline std::string topcom_program()
{
  for(const char* name : {"topcom-points2allfinetriangs", "points2allfinetriangs"})
    if(std::system((std::string("command -v ") + name + " > /dev/null 2>&1").c_str()) == 0) return name;
  throw Usage_error("TOPCOM is not installed (Debian: apt-get install topcom)");
}

// Every fine triangulation of `points` (at most `limit`), from TOPCOM.
inline std::vector<std::vector<std::array<std::size_t, 4>>> topcom_triangulations(const std::vector<Point>& points,
                                                                                  std::size_t limit, bool& truncated)
{
  const std::string program = topcom_program();
  const auto dir = std::filesystem::temp_directory_path();
  const std::string stem = (dir / ("edge_swap_topcom_" + std::to_string(::getpid()) + "_" +
                                   std::to_string(std::hash<std::thread::id>()(std::this_thread::get_id()))))
                               .string();
  // Both files go on every path out, errors included (a bad point set used to leave the input behind).
  struct Remove_on_exit
  {
    std::string stem;
    ~Remove_on_exit()
    {
      std::remove((stem + ".in").c_str());
      std::remove((stem + ".out").c_str());
    }
  } remove_on_exit{stem};
  {
    std::ofstream in(stem + ".in");
    try
    {
      CGAL::Edge_swapping_3::IO::write_topcom_points(in, points);
    }
    catch(const std::invalid_argument& e)
    {
      throw Usage_error(e.what());
    }
    in.close();
    if(!in) throw Usage_error("cannot write TOPCOM's input '" + stem + ".in'");
  }
  const std::string command = program + " < '" + stem + ".in' 2> /dev/null | head -n " + std::to_string(limit) +
                              " > '" + stem + ".out'";
  const int status = std::system(command.c_str());
  std::ifstream out(stem + ".out");
  auto triangulations = CGAL::Edge_swapping_3::IO::read_topcom_triangulations(out);
  if(status != 0 && triangulations.empty()) throw std::runtime_error("TOPCOM failed: " + command);
  truncated = triangulations.size() >= limit;
  return triangulations;
}

} // namespace edge_swap

#endif
