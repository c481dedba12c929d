// SPDX-License-Identifier: GPL-3.0-or-later
// What the writers share: no file the package writes holds nan or inf. A
// value that is not finite is refused with an error naming what it is, so
// that the all-or-nothing writer of the program writes nothing at all.

#ifndef CGAL_EDGE_SWAPPING_3_IO_TEXT_OUTPUT_H
#define CGAL_EDGE_SWAPPING_3_IO_TEXT_OUTPUT_H

#include <charconv>
#include <cmath>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

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

/// Formats text into a buffer with `std::to_chars` (no stream per number) and
/// hands it to the stream in large blocks. A double is written in its
/// shortest form that reads back to the same double.
class Text_sink
{
public:
  /// A sink that writes to `out`.
  explicit Text_sink(std::ostream& out) : out_(out) { buffer_.reserve(block + 64); }
  ~Text_sink() { flush(); }
  Text_sink(const Text_sink&) = delete;
  Text_sink& operator=(const Text_sink&) = delete;

  /// \name Appending text and numbers
  /// @{

  /// Appends `v` (a double in its shortest form that reads back the same).
  Text_sink& operator<<(double v) { return number(v); }
  Text_sink& operator<<(char c)
  {
    buffer_.push_back(c);
    return spill();
  }
  Text_sink& operator<<(std::string_view text)
  {
    buffer_.append(text);
    return spill();
  }
  Text_sink& operator<<(const char* text) { return *this << std::string_view(text); }
  Text_sink& operator<<(const std::string& text) { return *this << std::string_view(text); }
  template <class Integer, class = std::enable_if_t<std::is_integral<Integer>::value>>
  Text_sink& operator<<(Integer v) { return number(v); }
  /// @}

  /// Hands the buffer to the stream.

  void flush()
  {
    out_.write(buffer_.data(), std::streamsize(buffer_.size()));
    buffer_.clear();
  }

private:
  static constexpr std::size_t block = 1 << 20;

  template <class T>
  Text_sink& number(T v)
  {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, v).ptr;
    buffer_.append(text, end);
    return spill();
  }
  Text_sink& spill()
  {
    if(buffer_.size() >= block) flush();
    return *this;
  }

  std::ostream& out_;
  std::string buffer_;
};

} // namespace IO
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_IO_TEXT_OUTPUT_H
