// SPDX-License-Identifier: GPL-3.0-or-later
// Runs TOPCOM (Debian's topcom package) on a point set and reads every fine
// triangulation it enumerates.

#ifndef CGAL_EDGE_SWAPPING_3_IO_TOPCOM_RUNNER_H
#define CGAL_EDGE_SWAPPING_3_IO_TOPCOM_RUNNER_H

#include <CGAL/Edge_swapping_3/IO/topcom.h>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace IO {

/// \ingroup PkgEdgeSwapping3IO
/// What `topcom_triangulations()` returns.
struct Topcom_triangulations
{
  std::vector<std::vector<std::array<std::size_t, 4>>> triangulations; ///< each a list of tetrahedra (0-based)
  bool truncated = false; ///< the limit was reached: there may be more
};

/// \ingroup PkgEdgeSwapping3IO
/// The name of TOPCOM's enumerator of fine triangulations on this machine;
/// `std::runtime_error` when TOPCOM is not installed.
inline std::string topcom_program()
{
  for(const char* name : {"topcom-points2allfinetriangs", "points2allfinetriangs"})
    if(std::system((std::string("command -v ") + name + " > /dev/null 2>&1").c_str()) == 0) return name;
  throw std::runtime_error("TOPCOM is not installed (Debian: apt-get install topcom)");
}

/// \ingroup PkgEdgeSwapping3IO
/// Every fine triangulation of `points` (integer coordinates; at most
/// `limit`), enumerated by TOPCOM in files of the temporary folder that are
/// removed on every path out. Throws `std::invalid_argument` for points that
/// TOPCOM cannot read exactly, `std::runtime_error` when TOPCOM fails.
template <class Point>
Topcom_triangulations topcom_triangulations(const std::vector<Point>& points, std::size_t limit)
{
  const std::string program = topcom_program();
  const auto dir = std::filesystem::temp_directory_path();
  const std::string stem = (dir / ("edge_swapping_3_topcom_" + std::to_string(::getpid()) + "_" +
                                   std::to_string(std::hash<std::thread::id>()(std::this_thread::get_id()))))
                               .string();
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
    write_topcom_points(in, points);
    in.close();
    if(!in) throw std::runtime_error("cannot write TOPCOM's input '" + stem + ".in'");
  }
  const std::string command = program + " < '" + stem + ".in' 2> /dev/null | head -n " + std::to_string(limit) +
                              " > '" + stem + ".out'";
  const int status = std::system(command.c_str());
  std::ifstream out(stem + ".out");
  Topcom_triangulations result;
  result.triangulations = read_topcom_triangulations(out);
  if(status != 0 && result.triangulations.empty()) throw std::runtime_error("TOPCOM failed: " + command);
  result.truncated = result.triangulations.size() >= limit;
  return result;
}

} // namespace IO
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_IO_TOPCOM_RUNNER_H
