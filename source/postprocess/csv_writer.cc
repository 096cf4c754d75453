#include <tribos/base/write_atomically.h>
#include <tribos/postprocess/csv_writer.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iterator>
#include <sstream>

namespace tribos
{
  namespace
  {
    /** The fields of the CSV line @p line. */
    std::vector<std::string>
    fields_of(const std::string &line)
    {
      std::vector<std::string> fields;
      std::istringstream       in(line);
      std::string              field;
      while (std::getline(in, field, ','))
        fields.push_back(field);
      if (!line.empty() && line.back() == ',')
        fields.emplace_back();
      return fields;
    }



    /**
     * The rows of the earlier run's file @p filename through increment
     * @p keep, in the order of @p columns: a column the earlier run did
     * not write (Output/Probes added at the restart) is empty in its rows,
     * one it wrote and this run does not is dropped. A last line without
     * its end (a run killed while writing it) is dropped: it belongs to
     * an increment after the newest checkpoint. Any other line that is not
     * a row of the header's fields is refused, before anything of the
     * earlier run is changed.
     */
    std::vector<std::string>
    kept_rows(const std::string              &filename,
              const std::vector<std::string> &columns,
              const long                      keep)
    {
      std::ifstream in(filename, std::ios::binary);
      std::string   text;
      if (!in)
        return {};
      text.assign(std::istreambuf_iterator<char>(in),
                  std::istreambuf_iterator<char>());
      std::vector<std::string> lines;
      std::istringstream       stream(text);
      for (std::string line; std::getline(stream, line);)
        lines.push_back(line);
      if (!text.empty() && text.back() != '\n')
        lines.pop_back();
      if (lines.empty())
        return {};
      const std::vector<std::string> old_columns = fields_of(lines[0]);
      const auto                     position = [&](const std::string &column)
      {
        return std::find(old_columns.begin(), old_columns.end(), column) -
               old_columns.begin();
      };
      const long increment_column = position("increment");
      const auto refuse = [&](const std::size_t line, const std::string &what)
      {
        AssertThrow(false,
                    dealii::ExcMessage(
                      "The restart cannot continue <" + filename +
                      ">: its line " + std::to_string(line + 1) + " " + what +
                      ". Repair the line, or restart into a new Output/"
                      "Directory."));
      };
      if (increment_column == long(old_columns.size()))
        refuse(0, "is not the header of an earlier run (no column increment)");
      std::vector<std::string> kept;
      for (std::size_t l = 1; l < lines.size(); ++l)
      {
        const std::vector<std::string> fields = fields_of(lines[l]);
        if (fields.size() != old_columns.size())
          refuse(l,
                 "has " + std::to_string(fields.size()) +
                   " fields where the header has " +
                   std::to_string(old_columns.size()));
        const std::string &increment = fields[increment_column];
        char              *end       = nullptr;
        const long         value     = std::strtol(increment.c_str(), &end, 10);
        if (increment.empty() || *end != '\0' || value < 0)
          refuse(l, "has the increment <" + increment + ">, not a count");
        if (value > keep)
          continue;
        std::string row;
        for (unsigned int c = 0; c < columns.size(); ++c)
        {
          const long i = position(columns[c]);
          row += (c ? "," : "") +
                 (i < long(old_columns.size()) ? fields[i] : std::string());
        }
        kept.push_back(row);
      }
      return kept;
    }
  } // namespace



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
    const std::vector<std::string> kept =
      keep_through_increment >= 0 ?
        kept_rows(filename, columns, keep_through_increment) :
        std::vector<std::string>();
    // A restart's earlier rows go to a complete new file before it
    // replaces the old one: a run killed meanwhile leaves the old file
    // whole. A fresh run writes the file in place.
    const auto write_header = [&](std::ostream &out)
    {
      out << header << '\n';
      for (const auto &line : kept)
        out << line << '\n';
    };
    if (keep_through_increment >= 0)
      write_atomically(filename, write_header);
    else
    {
      file.open(filename);
      AssertThrow(file,
                  dealii::ExcMessage("Cannot open <" + filename +
                                     "> for writing: check Output/Directory."));
      write_header(file);
      file << std::flush;
      AssertThrow(file,
                  dealii::ExcMessage("Cannot write to <" + filename +
                                     "> (disk full?)."));
      return;
    }
    file.open(filename, std::ios::app);
    AssertThrow(file,
                dealii::ExcMessage("Cannot open <" + filename +
                                   "> for writing: check Output/Directory."));
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
