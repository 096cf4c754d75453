#include <tribos/base/text.h>

#include <deal.II/base/exceptions.h>

#include <cctype>
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
                                       ">: cannot read <" + piece +
                                       "> as a number in <" + text +
                                       ">. Expected a comma-separated "
                                       "list of numbers."));
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
