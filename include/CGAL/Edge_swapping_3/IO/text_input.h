// SPDX-License-Identifier: GPL-3.0-or-later
// What every reader of the package shares: the error that names the file,
// the line and the problem; reading a whole file (a regular file only);
// numbers parsed without streams, with range checks; and a scanner over the
// text that counts lines. The supported coordinate range is in
// point_set_checks.h.
//
// Every reader works on text in memory (`read_*_text(name, text)`), so that
// a fuzzer can feed it, and checks every count against the bytes that are
// left before it reserves anything.

#ifndef CGAL_EDGE_SWAPPING_3_IO_TEXT_INPUT_H
#define CGAL_EDGE_SWAPPING_3_IO_TEXT_INPUT_H

#include <CGAL/Edge_swapping_3/point_set_checks.h>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <sys/stat.h>
#include <system_error>
#include <type_traits>

namespace CGAL {
namespace Edge_swapping_3 {
namespace IO {

/// A file that cannot be read as what it claims to be. The message names the
/// file, the line where there is one, and the problem.
struct Input_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// `token`, quoted for a message: at most 40 characters, non-printable bytes as '?'.
inline std::string quote_token(std::string_view token)
{
  std::string s = "'";
  for(std::size_t k = 0; k < token.size() && k < 40; ++k)
    s += (token[k] >= 32 && token[k] < 127) ? token[k] : '?';
  if(token.size() > 40) s += "...";
  return s + "'";
}

/// The whole content of the file at `path`. Throws Input_error naming the file
/// if it is missing, not a regular file (a directory, a device, a pipe) or
/// cannot be read.
inline std::string read_text_file(const std::string& path)
{
  struct stat st;
  if(::stat(path.c_str(), &st) != 0) throw Input_error(path + ": cannot open the file (" + std::strerror(errno) + ")");
  if(S_ISDIR(st.st_mode)) throw Input_error(path + ": is a directory, not a file");
  if(!S_ISREG(st.st_mode)) throw Input_error(path + ": is not a regular file");
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if(!f) throw Input_error(path + ": cannot open the file (" + std::strerror(errno) + ")");
  std::string text;
  text.resize(std::size_t(st.st_size));
  const std::size_t got = text.empty() ? 0 : std::fread(&text[0], 1, text.size(), f);
  const bool failed = std::ferror(f) != 0;
  std::fclose(f);
  if(failed) throw Input_error(path + ": cannot read the file");
  text.resize(got); // a file that shrank while being read
  return text;
}

namespace internal {

enum class Number_status { ok, not_a_number, out_of_range };

/// Parses all of `token` as a `T` (an integer or a double): no stream, no
/// locale. A leading '+' is accepted, as by strtod.
template <class T>
Number_status parse_number(std::string_view token, T& value)
{
  if(token.size() > 1 && token[0] == '+' && token[1] != '-') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  if(ec == std::errc::result_out_of_range) return Number_status::out_of_range;
  if(ec != std::errc() || ptr != end) return Number_status::not_a_number;
  return Number_status::ok;
}

/// Walks over a text, token by token, counting lines. '#' starts a comment
/// that runs to the end of the line. Tokens are separated by white space.
class Text_scanner
{
public:
  Text_scanner(std::string name, std::string_view text) : name_(std::move(name)), text_(text) {}

  /// The next token on any line; false at the end of the text.
  bool next_token(std::string_view& token)
  {
    for(;;)
    {
      skip_blanks();
      if(pos_ == text_.size()) return false;
      const char ch = text_[pos_];
      if(ch == '\n') { ++pos_; ++line_; line_started_ = false; continue; }
      if(ch == '#') { skip_to_end_of_line(); continue; }
      break;
    }
    token = take_token();
    return true;
  }

  /// Moves to the next line that has a token; false at the end of the text.
  bool next_line()
  {
    if(line_started_) skip_to_end_of_line();
    for(;;)
    {
      skip_blanks();
      if(pos_ == text_.size()) return false;
      const char ch = text_[pos_];
      if(ch == '\n') { ++pos_; ++line_; continue; }
      if(ch == '#') { skip_to_end_of_line(); continue; }
      line_started_ = true;
      return true;
    }
  }

  /// The next token of the current line; false at its end.
  bool next_token_in_line(std::string_view& token)
  {
    if(!line_has_more()) return false;
    token = take_token();
    return true;
  }

  /// Whether the current line has another token.
  bool line_has_more()
  {
    skip_blanks();
    return pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '#';
  }

  /// Bytes not yet read: no count of entries can be larger than this allows.
  std::size_t remaining_bytes() const { return text_.size() - pos_; }

  [[noreturn]] void fail(const std::string& what) const
  {
    throw Input_error(name_ + ":" + std::to_string(line_) + ": " + what);
  }

  /// `token` as a `T`, or an error that names `what` and the token. Doubles
  /// must be finite; the caller checks their range. (`what` is a view: a
  /// string made per number was 2.5% of `check` at 10^6 points.)
  template <class T>
  T number(std::string_view token, std::string_view what) const
  {
    T value{};
    const Number_status status = parse_number(token, value);
    if(status == Number_status::ok)
    {
      if constexpr(std::is_floating_point<T>::value)
        if(!std::isfinite(value)) fail(std::string(what) + " is not finite: " + quote_token(token));
      return value;
    }
    const std::string name(what);
    if(status == Number_status::out_of_range)
    {
      if constexpr(std::is_floating_point<T>::value)
      {
        // from_chars says so for overflow and for underflow alike.
        double magnitude = 0;
        std::sscanf(std::string(token.substr(0, 64)).c_str(), "%lf", &magnitude);
        if(std::isinf(magnitude)) fail(name + " is not finite (too large for a double): " + quote_token(token));
        fail(name + " is too small for a double: " + quote_token(token));
      }
      fail(name + " is out of range: " + quote_token(token));
    }
    fail("cannot read " + name + " from " + quote_token(token));
  }

  /// Whether `n` entries of at least `min_bytes` each (a separator
  /// included, but for the last) fit in what is left.
  bool has_room(std::size_t n, std::size_t min_bytes) const { return n <= (remaining_bytes() + 1) / min_bytes; }

  /// A count of entries that must each take at least `min_bytes` of what is left.
  std::size_t count(std::string_view token, std::string_view what, std::size_t min_bytes) const
  {
    const long long n = number<long long>(token, what);
    if(n < 0) fail("negative " + std::string(what) + ": " + quote_token(token));
    if(!has_room(std::size_t(n), min_bytes))
      fail(std::string(what) + " is " + std::to_string(n) + ", more than the rest of the file can hold (" +
           std::to_string(remaining_bytes()) + " bytes)");
    return std::size_t(n);
  }

private:
  void skip_blanks()
  {
    while(pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\r' ||
                                  text_[pos_] == '\v' || text_[pos_] == '\f'))
      ++pos_;
  }

  void skip_to_end_of_line()
  {
    while(pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    line_started_ = false;
  }

  std::string_view take_token()
  {
    if(!line_started_) line_started_ = true;
    const std::size_t begin = pos_;
    while(pos_ < text_.size())
    {
      const char ch = text_[pos_];
      if(ch == ' ' || ch == '\t' || ch == '\r' || ch == '\n' || ch == '\v' || ch == '\f' || ch == '#') break;
      ++pos_;
    }
    return text_.substr(begin, pos_ - begin);
  }

  std::string name_;
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
  bool line_started_ = false;
};

} // namespace internal
} // namespace IO
} // namespace Edge_swapping_3
} // namespace CGAL

#endif // CGAL_EDGE_SWAPPING_3_IO_TEXT_INPUT_H
