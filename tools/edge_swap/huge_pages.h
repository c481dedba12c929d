// SPDX-License-Identifier: GPL-3.0-or-later
// Huge pages for the program's heap, through glibc's own switch.
//
// A mesh of a million points takes about a gigabyte. On this project's
// machine (a virtual machine) each 4 KiB page fault costs about 20 µs, so
// first touching the file text, the cells read and the triangulation took
// several seconds of `check` at 10^6 points. Where transparent huge pages are
// "madvise" only (Debian 12's setting), glibc advises its heap as huge pages
// when the tunable glibc.malloc.hugetlb is 1; tunables are read at start-up
// only, so the program starts itself again with it set. Elsewhere (huge pages
// "always" or "never", an older glibc) the tunable changes nothing. A user's
// GLIBC_TUNABLES that already sets it (to 0, say) is left alone. The library
// does none of this: a user's program decides for itself.

#ifndef EDGE_SWAP_HUGE_PAGES_H
#define EDGE_SWAP_HUGE_PAGES_H

#include <cstdlib>
#include <string>
#include <unistd.h>

namespace edge_swap {

/// Starts the program again with glibc's huge-page tunable on, unless it is
/// set already; returns (and runs on as it is) if that fails.
inline void restart_with_huge_pages(char** argv)
{
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  const std::string current = tunables ? tunables : "";
  if(current.find("glibc.malloc.hugetlb") != std::string::npos) return;
  const std::string wanted = (current.empty() ? "" : current + ":") + "glibc.malloc.hugetlb=1";
  if(::setenv("GLIBC_TUNABLES", wanted.c_str(), 1) != 0) return;
  ::execv("/proc/self/exe", argv);
  // Not restarted (no /proc, say): the same program, with 4 KiB pages.
  if(tunables) ::setenv("GLIBC_TUNABLES", current.c_str(), 1);
  else ::unsetenv("GLIBC_TUNABLES");
}

} // namespace edge_swap

#endif
