#include <tribos/postprocess/csv_writer.h>

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace tribos
{
  CsvWriter::CsvWriter(const std::string              &filename,
                       const std::vector<std::string> &columns,
                       const bool                      active)
    : columns(columns)
    , active(active)
  {
    if (!active)
      return;
    file.open(filename);
    AssertThrow(file,
                dealii::ExcMessage("Cannot open <" + filename +
                                   "> for writing: check Output/Directory."));
    for (unsigned int i = 0; i < columns.size(); ++i)
      file << (i ? "," : "") << columns[i];
    file << '\n' << std::flush;
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
  }
} // namespace tribos
