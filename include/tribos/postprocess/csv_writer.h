#ifndef tribos_postprocess_csv_writer_h
#define tribos_postprocess_csv_writer_h

#include <fstream>
#include <string>
#include <vector>

namespace tribos
{
  /**
   * A CSV file with a fixed header, written row by row and flushed after
   * every row, so that a run that stops keeps every complete row. Only the
   * process that is told to be active writes (rank 0 under MPI).
   */
  class CsvWriter
  {
  public:
    /**
     * With @p keep_through_increment >= 0 (a restart) an existing file
     * keeps its rows whose column "increment" is at most that (in this
     * run's columns: one the earlier run lacked is empty there), and rows
     * are appended after them; otherwise the file starts anew. The file is
     * replaced atomically; a malformed earlier file is refused with its
     * line before it is changed.
     */
    CsvWriter(const std::string              &filename,
              const std::vector<std::string> &columns,
              const bool                      active,
              const long                      keep_through_increment = -1);

    /** Append one row; the number of values must match the header. */
    void
    add_row(const std::vector<double> &values);

    unsigned int
    n_columns() const
    {
      return columns.size();
    }

  private:
    const std::string              filename;
    const std::vector<std::string> columns;
    const bool                     active;
    std::ofstream                  file;
  };
} // namespace tribos

#endif
