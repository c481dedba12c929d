// SPDX-License-Identifier: GPL-3.0-or-later
// Runs TOPCOM (Debian's topcom package) on a point set and reads every fine
// triangulation it enumerates.

#ifndef CGAL_EDGE_SWAPPING_3_LABORATORY_IO_TOPCOM_RUNNER_H
#define CGAL_EDGE_SWAPPING_3_LABORATORY_IO_TOPCOM_RUNNER_H

#include <CGAL/Edge_swapping_3/Laboratory/IO/topcom.h>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <stdio.h>
#include <stdlib.h>
#include <string>
#include <string_view>
#include <unistd.h>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace IO {

/// \ingroup PkgEdgeSwapping3Laboratory
/// What `topcom_triangulations()` returns.
struct Topcom_triangulations
{
  std::vector<std::vector<std::array<std::size_t, 4>>> triangulations; ///< each a list of tetrahedra (0-based)
  bool truncated = false; ///< the limit was reached: there may be more
};

/// \ingroup PkgEdgeSwapping3Laboratory
/// The name of TOPCOM's enumerator of fine triangulations on this machine;
/// `std::runtime_error` when TOPCOM is not installed.
inline std::string topcom_program()
{
  for(const char* name : {"topcom-points2allfinetriangs", "points2allfinetriangs"})
    if(std::system((std::string("command -v ") + name + " > /dev/null 2>&1").c_str()) == 0) return name;
  throw std::runtime_error("TOPCOM is not installed (Debian: apt-get install topcom)");
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// Streams every fine triangulation of `points` (integer coordinates) as
/// TOPCOM enumerates it, without holding them: calls `visit(index, cells)`
/// for each (`cells`: its tetrahedra, 0-based point indices), until
/// `visit` returns false or `limit` have been visited. Returns the number
/// visited. TOPCOM reads its input from a file of the temporary folder that
/// is unlinked as soon as it is made, so none is left when the process is
/// killed while TOPCOM runs. Throws `std::invalid_argument` for points
/// that TOPCOM cannot read exactly, `std::runtime_error` when TOPCOM fails
/// (also after some triangulations were visited: a list cut short is not
/// taken for the whole), and what `visit` throws.
template <class Point, class Visit>
std::size_t for_each_topcom_triangulation(const std::vector<Point>& points, std::size_t limit, Visit visit)
{
  const std::string program = topcom_program();
  std::ostringstream text;
  write_topcom_points(text, points); // throws before any file exists
  const std::string input = text.str();
  // Unlinked as soon as it is made: TOPCOM reads it through /dev/fd, and a
  // process killed by a signal while TOPCOM runs leaves nothing in the temporary folder.
  std::string name = (std::filesystem::temp_directory_path() / "edge_swapping_3_topcom_XXXXXX").string();
  struct Descriptor
  {
    int fd;
    ~Descriptor()
    {
      if(fd >= 0) ::close(fd);
    }
  } input_file{::mkstemp(name.data())};
  if(input_file.fd < 0) throw std::runtime_error("cannot create TOPCOM's input file '" + name + "'");
  ::unlink(name.c_str());
  for(std::size_t written = 0; written < input.size();)
  {
    const ssize_t n = ::write(input_file.fd, input.data() + written, input.size() - written);
    if(n < 0 && errno == EINTR) continue;
    if(n <= 0) throw std::runtime_error("cannot write TOPCOM's input file '" + name + "'");
    written += std::size_t(n);
  }
  // Where /dev/fd duplicates the descriptor (not Linux, which opens the file anew), it reads from here.
  ::lseek(input_file.fd, 0, SEEK_SET);
  const std::string command = program + " < /dev/fd/" + std::to_string(input_file.fd) + " 2> /dev/null";
  // Closed on every path out; a TOPCOM still writing when we stop ends on SIGPIPE.
  struct Pipe
  {
    FILE* file;
    char* buffer = nullptr;
    ~Pipe()
    {
      std::free(buffer);
      if(file) ::pclose(file);
    }
  } pipe{::popen(command.c_str(), "r")};
  if(!pipe.file) throw std::runtime_error("cannot start TOPCOM: " + command);
  std::size_t capacity = 0, line_number = 0, visited = 0;
  std::vector<std::array<std::size_t, 4>> cells;
  bool stopped = false;
  for(ssize_t length; visited < limit && (length = ::getline(&pipe.buffer, &capacity, pipe.file)) >= 0;)
  {
    std::string_view line(pipe.buffer, std::size_t(length));
    if(!line.empty() && line.back() == '\n') line.remove_suffix(1);
    if(!read_topcom_triangulation_line(line, ++line_number, cells)) continue;
    if(!visit(visited++, cells))
    {
      stopped = true;
      break;
    }
  }
  if(visited < limit && !stopped)
  {
    const int status = ::pclose(pipe.file);
    pipe.file = nullptr;
    // TOPCOM ends with 0 when its list is whole: a list cut short by a crash is not a count.
    if(status != 0)
      throw std::runtime_error("TOPCOM failed after " + std::to_string(visited) + " triangulations: " + command);
  }
  return visited;
}

/// \ingroup PkgEdgeSwapping3Laboratory
/// Every fine triangulation of `points` (integer coordinates; at most
/// `limit`), held in memory; see `for_each_topcom_triangulation()`.
template <class Point>
Topcom_triangulations topcom_triangulations(const std::vector<Point>& points, std::size_t limit)
{
  Topcom_triangulations result;
  for_each_topcom_triangulation(points, limit, [&](std::size_t, const std::vector<std::array<std::size_t, 4>>& cells) {
    result.triangulations.push_back(cells);
    return true;
  });
  result.truncated = result.triangulations.size() >= limit;
  return result;
}

} // namespace IO
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_LABORATORY_IO_TOPCOM_RUNNER_H
