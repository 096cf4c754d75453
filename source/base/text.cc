#include <tribos/base/text.h>

#include <deal.II/base/exceptions.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace tribos
{
  namespace Text
  {
    std::string
    trim(const std::string &text)
    {
      const auto first = text.find_first_not_of(" \t\n\r");
      if (first == std::string::npos)
        return "";
      const auto last = text.find_last_not_of(" \t\n\r");
      return text.substr(first, last - first + 1);
    }



    std::string
    abbreviate(const std::string &text, const std::size_t max_length)
    {
      std::string       shown;
      std::size_t       n_shown = 0, i = 0;
      const std::size_t n   = text.size();
      const auto        hex = [](const unsigned long value, const int width)
      {
        char buffer[16];
        std::snprintf(buffer, sizeof(buffer), "%0*lX", width, value);
        return std::string(buffer);
      };
      for (; i < n && n_shown < max_length; ++n_shown)
      {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c < 0x80)
        {
          shown += (c < 0x20 || c == 0x7F) ? "<0x" + hex(c, 2) + ">" :
                                             std::string(1, text[i]);
          ++i;
          continue;
        }
        // A UTF-8 sequence: its length from the lead byte.
        const std::size_t length = (c >= 0xF0) ? 4 :
                                   (c >= 0xE0) ? 3 :
                                   (c >= 0xC0) ? 2 :
                                                 0;
        bool              valid  = length > 0 && i + length <= n;
        for (std::size_t k = 1; valid && k < length; ++k)
          valid = (static_cast<unsigned char>(text[i + k]) & 0xC0) == 0x80;
        if (!valid)
        {
          shown += "<0x" + hex(c, 2) + ">";
          ++i;
          continue;
        }
        unsigned long code = c & (0xFF >> (length + 1));
        for (std::size_t k = 1; k < length; ++k)
          code = (code << 6) | (static_cast<unsigned char>(text[i + k]) & 0x3F);
        const bool invisible =
          code == 0xA0 || code == 0xAD || (code >= 0x2000 && code <= 0x200F) ||
          (code >= 0x2028 && code <= 0x202F) || code == 0x2060 ||
          code == 0xFEFF || code == 0x3000 || (code >= 0x80 && code < 0xA0);
        shown +=
          invisible ? "<U+" + hex(code, 4) + ">" : text.substr(i, length);
        i += length;
      }
      if (i < n)
        shown += "... (" + std::to_string(n) + " bytes)";
      return shown;
    }



    std::vector<std::string>
    split_top_level(const std::string &text, const char separator)
    {
      std::vector<std::string> pieces;
      if (trim(text).empty())
        return pieces;

      int         depth = 0;
      std::string current;
      for (const char c : text)
      {
        if (c == '(')
          ++depth;
        else if (c == ')')
          --depth;

        if (c == separator && depth == 0)
        {
          pieces.push_back(trim(current));
          current.clear();
        }
        else
          current += c;
      }
      pieces.push_back(trim(current));
      return pieces;
    }



    std::vector<double>
    parse_doubles(const std::string &text, const std::string &entry)
    {
      std::vector<double> values;
      for (const auto &piece : split_top_level(text, ','))
      {
        char        *end   = nullptr;
        const double value = std::strtod(piece.c_str(), &end);
        AssertThrow(!piece.empty() && end != nullptr && *end == '\0',
                    dealii::ExcMessage("Parameter <" + entry +
                                       ">: cannot read <" + abbreviate(piece) +
                                       "> as a number in <" + abbreviate(text) +
                                       ">. Expected a comma-separated "
                                       "list of numbers."));
        AssertThrow(std::isfinite(value) && std::abs(value) <= largest_value &&
                      (value == 0 || std::abs(value) >= 1. / largest_value),
                    dealii::ExcMessage(
                      "Parameter <" + entry + ">: <" + abbreviate(piece) +
                      "> in <" + abbreviate(text) +
                      "> is not 0 or a finite number of magnitude between "
                      "1e-150 and 1e150 (products of two input values must "
                      "neither overflow nor underflow)."));
        values.push_back(value);
      }
      return values;
    }



    std::vector<unsigned int>
    parse_unsigned(const std::string &text, const std::string &entry)
    {
      std::vector<unsigned int> values;
      for (const auto &piece : split_top_level(text, ','))
      {
        char      *end   = nullptr;
        const long value = std::strtol(piece.c_str(), &end, 10);
        AssertThrow(!piece.empty() && *end == '\0' && value >= 0,
                    dealii::ExcMessage(
                      "Parameter <" + entry + ">: cannot read <" + piece +
                      "> as a non-negative integer in <" + text + ">."));
        values.push_back(static_cast<unsigned int>(value));
      }
      return values;
    }



    double
    positive(dealii::ParameterHandler &prm, const std::string &entry)
    {
      const double v = prm.get_double(entry);
      AssertThrow(v > 0,
                  dealii::ExcMessage("Parameter <" + entry + "> = <" +
                                     prm.get(entry) + ">: must be > 0."));
      return v;
    }



    std::vector<double>
    positive_list(dealii::ParameterHandler &prm, const std::string &entry)
    {
      const auto values = parse_doubles(prm.get(entry), entry);
      for (const double v : values)
        AssertThrow(v > 0,
                    dealii::ExcMessage("Parameter <" + entry + "> = <" +
                                       prm.get(entry) +
                                       ">: every value must be > 0."));
      return values;
    }



    std::vector<unsigned int>
    cell_counts(dealii::ParameterHandler &prm, const std::string &entry)
    {
      const auto values = parse_unsigned(prm.get(entry), entry);
      for (const unsigned int v : values)
        AssertThrow(v > 0,
                    dealii::ExcMessage("Parameter <" + entry + "> = <" +
                                       prm.get(entry) +
                                       ">: every cell count must be >= 1."));
      return values;
    }
  } // namespace Text
} // namespace tribos
