// SPDX-License-Identifier: GPL-3.0-or-later
// Several output files written all or nothing, as the programs write theirs.
// Every output path is checked before any work (not a directory, a folder
// that exists and can be written, no two outputs the same). Each file is
// written to a temporary
// `OUT.edge_swap-partial-PID` beside it, every write and the close checked;
// only when all are complete are they renamed, and a failed rename puts back
// the files it replaced. A run that is killed leaves its partial files; the
// next run that writes the same output removes those whose process is gone.

#ifndef CGAL_EDGE_SWAPPING_3_IO_OUTPUT_FILES_H
#define CGAL_EDGE_SWAPPING_3_IO_OUTPUT_FILES_H

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace CGAL {
namespace Edge_swapping_3 {
namespace IO {

/// \ingroup PkgEdgeSwapping3IO
/// An output that cannot be written: the message names the file and the problem.
struct Output_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

namespace internal_output {

namespace fs = std::filesystem;

inline const std::string partial_tag = ".edge_swap-partial-";
inline const std::string backup_tag = ".edge_swap-backup-";

inline std::string temporary_name(const std::string& path, const std::string& tag)
{
  return path + tag + std::to_string(::getpid());
}

// Removes `path`'s partial files left by runs whose process no longer exists.
inline void remove_stale_partial_files(const std::string& path)
{
  const fs::path p(path);
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  const std::string prefix = p.filename().string() + partial_tag;
  std::error_code ec;
  for(fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
  {
    const std::string name = it->path().filename().string();
    if(name.rfind(prefix, 0) != 0) continue;
    const std::string pid = name.substr(prefix.size());
    if(pid.empty() || pid.size() > 9 || pid.find_first_not_of("0123456789") != std::string::npos) continue;
    if(::kill(pid_t(std::stol(pid)), 0) == -1 && errno == ESRCH) fs::remove(it->path(), ec);
  }
}

} // namespace internal_output

/// \ingroup PkgEdgeSwapping3IO
/// Checks, before any work, that the non-empty `paths` can be written as
/// outputs; throws Output_error naming the path and the problem. Removes the
/// stale partial files of each.
inline void check_output_paths(const std::vector<std::string>& paths)
{
  namespace fs = std::filesystem;
  std::set<std::string> seen;
  for(const std::string& path : paths)
  {
    if(path.empty()) continue;
    std::error_code ec;
    const fs::path p(path);
    if(fs::is_directory(p, ec)) throw Output_error("output '" + path + "' is a directory");
    if(fs::exists(p, ec) && !fs::is_regular_file(p, ec)) throw Output_error("output '" + path + "' is not a regular file");
    const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
    if(!fs::is_directory(dir, ec)) throw Output_error("output '" + path + "': the folder '" + dir.string() + "' does not exist");
    if(::access(dir.c_str(), W_OK) != 0) throw Output_error("output '" + path + "': the folder '" + dir.string() + "' cannot be written");
    const std::string key = fs::absolute(p, ec).lexically_normal().string();
    if(!seen.insert(key).second) throw Output_error("output '" + path + "' is named twice");
    internal_output::remove_stale_partial_files(path);
  }
}

/// \ingroup PkgEdgeSwapping3IO
/// Writes several files all or nothing. Each writer fills a stream; a writer
/// that throws (a value it refuses, such as one that is not finite) makes
/// `commit()` write nothing and throw Output_error with its message.
class Output_files
{
public:
  /// Adds the file `path`, which `writer` fills when `commit()` runs.
  void add(const std::string& path, std::function<void(std::ostream&)> writer)
  {
    files_.push_back({path, std::move(writer)});
  }

  /// Writes every file added, or none: throws Output_error naming the file that failed.
  void commit()
  {
    using namespace internal_output;
    std::vector<std::string> temporary, backups;
    std::size_t renamed = 0;
    auto undo = [&](const std::string& what) {
      for(std::size_t k = 0; k < renamed; ++k)
      {
        if(!backups[k].empty()) std::rename(backups[k].c_str(), files_[k].path.c_str());
        else std::remove(files_[k].path.c_str());
      }
      for(std::size_t k = renamed; k < backups.size(); ++k)
        if(!backups[k].empty()) std::remove(backups[k].c_str());
      for(const auto& t : temporary) std::remove(t.c_str());
      throw Output_error(what);
    };
    for(const auto& f : files_)
    {
      temporary.push_back(temporary_name(f.path, partial_tag));
      std::ofstream out(temporary.back(), std::ios::binary);
      errno = 0;
      std::string refused; // a writer that refuses its data (a value that is not finite)
      try
      {
        if(out) f.writer(out);
      }
      catch(const std::exception& e)
      {
        refused = e.what();
      }
      out.flush();
      out.close();
      if(!refused.empty()) undo("cannot write '" + f.path + "': " + refused);
      if(!out) undo("cannot write '" + f.path + "'" + (errno ? std::string(": ") + std::strerror(errno) : std::string()));
    }
    // Keep what each output replaces until all are in place.
    for(const auto& f : files_)
    {
      backups.emplace_back();
      struct stat st;
      if(::stat(f.path.c_str(), &st) == 0)
      {
        const std::string b = temporary_name(f.path, backup_tag);
        std::remove(b.c_str());
        if(::link(f.path.c_str(), b.c_str()) == 0) backups.back() = b;
      }
    }
    for(; renamed < files_.size(); ++renamed)
      if(std::rename(temporary[renamed].c_str(), files_[renamed].path.c_str()) != 0)
        undo("cannot write '" + files_[renamed].path + "': " + std::strerror(errno));
    for(const auto& b : backups)
      if(!b.empty()) std::remove(b.c_str());
  }

private:
  struct File { std::string path; std::function<void(std::ostream&)> writer; };
  std::vector<File> files_;
};

} // namespace IO
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_IO_OUTPUT_FILES_H
