// What the writers share: no file the package writes holds nan or inf. A
// value that is not finite is refused with an error naming what it is, so
// that the all-or-nothing writer of the program writes nothing at all.

#ifndef CGAL_EDGE_SWAPPING_3_IO_TEXT_OUTPUT_H
#define CGAL_EDGE_SWAPPING_3_IO_TEXT_OUTPUT_H

#include <cmath>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Edge_swapping_3 {
namespace IO {

/// `v` if it is finite; otherwise throws std::domain_error naming `what`
/// (and the field, if given). The message is made only then: writers call
/// this for every number.
inline double finite_value(double v, const char* what, const std::string* field = nullptr)
{
  if(!std::isfinite(v))
    throw std::domain_error(std::string(what) + (field ? " of field '" + *field + "'" : std::string()) +
                            " is not a finite number");
  return v;
}

} // namespace IO
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_IO_TEXT_OUTPUT_H
