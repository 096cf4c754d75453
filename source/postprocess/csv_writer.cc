#include <tribos/postprocess/csv_writer.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace tribos
{
  CsvWriter::CsvWriter(const std::string              &filename,
                       const std::vector<std::string> &columns,
                       const bool                      active,
                       const long                      keep_through_increment)
    : filename(filename)
    , columns(columns)
    , active(active)
  {
    if (!active)
      return;
    std::string header;
    for (unsigned int i = 0; i < columns.size(); ++i)
      header += (i ? "," : "") + columns[i];

    std::vector<std::string> kept;
    const auto               increment_column =
      std::find(columns.begin(), columns.end(), "increment") - columns.begin();
    if (keep_through_increment >= 0 && increment_column < long(columns.size()))
    {
      std::ifstream in(filename);
      std::string   line;
      if (in && std::getline(in, line) && line == header)
        while (std::getline(in, line))
        {
          std::istringstream fields(line);
          std::string        field;
          for (long i = 0; i <= increment_column; ++i)
            std::getline(fields, field, ',');
          if (!field.empty() && std::stol(field) <= keep_through_increment)
            kept.push_back(line);
        }
    }
    file.open(filename);
    AssertThrow(file,
                dealii::ExcMessage("Cannot open <" + filename +
                                   "> for writing: check Output/Directory."));
    file << header << '\n';
    for (const auto &line : kept)
      file << line << '\n';
    file << std::flush;
    AssertThrow(file,
                dealii::ExcMessage("Cannot write to <" + filename +
                                   "> (disk full?)."));
  }



  void
  CsvWriter::add_row(const std::vector<double> &values)
  {
    Assert(values.size() == columns.size(),
           dealii::ExcDimensionMismatch(values.size(), columns.size()));
    if (!active)
      return;
    std::ostringstream row;
    row << std::setprecision(10);
    for (unsigned int i = 0; i < values.size(); ++i)
    {
      if (i)
        row << ',';
      // Integers (counters, ids) print without exponent or decimals.
      if (values[i] == std::floor(values[i]) && std::abs(values[i]) < 1e15)
        row << static_cast<long long>(values[i]);
      else
        row << values[i];
    }
    file << row.str() << '\n' << std::flush;
    AssertThrow(file,
                dealii::ExcMessage("Cannot write to <" + filename +
                                   "> (disk full?)."));
  }
} // namespace tribos
