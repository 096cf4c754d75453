#ifndef tribos_base_text_h
#define tribos_base_text_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace tribos
{
  /**
   * Small string helpers for the structured entries of the parameter file
   * (boundary-condition lists, per-body lists). They live here so that every
   * parser splits and reports errors the same way.
   */
  namespace Text
  {
    /**
     * The largest magnitude a number of the input may have: products of
     * two such numbers stay finite (1e308 as a Young's modulus made the
     * penalty and the residual infinite, reported as a non-convergence).
     * Nonzero numbers of a list are also at least its inverse: 1e-308 as a
     * Young's modulus underflowed to a residual of round-off.
     */
    constexpr double largest_value = 1e150;

    /** The pattern of a number entry: any number within +-largest_value. */
    inline dealii::Patterns::Double
    any_number()
    {
      return dealii::Patterns::Double(-largest_value, largest_value);
    }

    /** The pattern of a number entry >= 0 (and <= largest_value). */
    inline dealii::Patterns::Double
    non_negative_number()
    {
      return dealii::Patterns::Double(0, largest_value);
    }

    /**
     * Split @p text at every @p separator that is not inside parentheses, so
     * that function expressions such as `if(t<1, t, 1)` survive a split at
     * commas. Pieces are trimmed; empty input gives an empty list.
     */
    std::vector<std::string>
    split_top_level(const std::string &text, const char separator);

    /**
     * @p text as an error message may quote it: characters that do not
     * show (control characters, no-break and zero-width spaces, a byte
     * order mark, bytes that are not UTF-8) written as <U+XXXX> or <0xXX>,
     * and at most @p max_length characters of it, with the total length
     * said after an ellipsis.
     */
    std::string
    abbreviate(const std::string &text, const std::size_t max_length = 200);

    /** The numbers of @p values as "1, 2, 5" (for messages). */
    template <typename Container>
    std::string
    join(const Container &values)
    {
      std::string text;
      for (const auto &v : values)
        text += (text.empty() ? "" : ", ") + std::to_string(v);
      return text.empty() ? "none" : text;
    }

    /** Remove leading and trailing white space. */
    std::string
    trim(const std::string &text);

    /**
     * Parse a list of doubles written as "a, b, c" for the entry @p entry
     * (used in error messages). Throws with a message naming the entry.
     */
    std::vector<double>
    parse_doubles(const std::string &text, const std::string &entry);

    /** Like parse_doubles() for non-negative integers. */
    std::vector<unsigned int>
    parse_unsigned(const std::string &text, const std::string &entry);

    /** The double entry @p entry of @p prm, which must be > 0. */
    double
    positive(dealii::ParameterHandler &prm, const std::string &entry);

    /** The list entry @p entry of @p prm, every value > 0. */
    std::vector<double>
    positive_list(dealii::ParameterHandler &prm, const std::string &entry);

    /** The list of cell counts @p entry of @p prm, every one >= 1. */
    std::vector<unsigned int>
    cell_counts(dealii::ParameterHandler &prm, const std::string &entry);
  } // namespace Text
} // namespace tribos

#endif
