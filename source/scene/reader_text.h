#ifndef tribos_scene_reader_text_h
#define tribos_scene_reader_text_h

/**
 * The token helpers the mesh-file readers share (not an interface): the
 * gmsh reader (msh_file*.cc) and the Abaqus/CalculiX reader (inp_*.cc) trim,
 * parse numbers and quote a file's text for their messages the same way.
 */

#include <tribos/base/text.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>
#include <system_error>

namespace tribos
{
  namespace internal::ReaderText
  {
    inline bool
    is_space(const char c)
    {
      return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
    }

    /** @p s without surrounding blanks. */
    inline std::string_view
    trim(std::string_view s)
    {
      while (!s.empty() && is_space(s.back()))
        s.remove_suffix(1);
      while (!s.empty() && is_space(s.front()))
        s.remove_prefix(1);
      return s;
    }

    /** @p s quoted for a message: its start, with non-printing bytes as
     * '?', since the file may be binary. */
    inline std::string
    quote(const std::string_view s)
    {
      std::string q = "'";
      for (std::size_t i = 0; i < s.size() && i < 40; ++i)
        q += (s[i] < 32 || s[i] > 126) ? '?' : s[i];
      return q + (s.size() > 40 ? "...'" : "'");
    }

    /** Whether @p s is a finite double, into @p value (a leading '+'
     * allowed, as strtod has it). */
    inline bool
    parse_finite(std::string_view s, double &value)
    {
      if (s.size() > 1 && s[0] == '+' && s[1] != '-' && s[1] != '+')
        s.remove_prefix(1);
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
      const char *end = s.data() + s.size();
      const auto  r   = std::from_chars(s.data(), end, value);
      if (r.ptr != end)
        return false;
      if (r.ec == std::errc::result_out_of_range) // 1e999 refused, 1e-400 0
        value = std::strtod(std::string(s).c_str(), nullptr);
      else if (r.ec != std::errc())
        return false;
#else
      const std::string copy(s);
      char             *end = nullptr;
      value                 = std::strtod(copy.c_str(), &end);
      if (copy.empty() || end != copy.c_str() + copy.size() ||
          copy.find_first_of("xXnN") != std::string::npos)
        return false;
#endif
      return std::isfinite(value);
    }

    /**
     * Whether a node's coordinate @p value is within the input's range,
     * |value| <= Text::largest_value (1e150, the README's bound on every
     * number of the input): the geometry multiplies coordinates (lengths,
     * areas, Jacobians), and x = 1e300 overflowed there, to a cell
     * reported as degenerate without a word of the number or its line.
     */
    inline bool
    coordinate_in_range(const double value)
    {
      return std::abs(value) <= Text::largest_value;
    }

    /** The message of a coordinate @p s out of that range. */
    inline std::string
    coordinate_out_of_range(const std::string_view s)
    {
      return quote(s) + " is out of range for a coordinate (numbers of the "
                        "input are at most 1e150 in magnitude)";
    }
  } // namespace internal::ReaderText
} // namespace tribos

#endif
