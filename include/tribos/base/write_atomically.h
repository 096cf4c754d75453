#ifndef tribos_base_write_atomically_h
#define tribos_base_write_atomically_h

#include <deal.II/base/exceptions.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace tribos
{
  /**
   * Write @p filename through a temporary file that replaces it only once
   * it is complete, so that neither a failed write (a full disk) nor an
   * interrupted run leaves a half-written file, and the earlier version
   * stays until the new one is whole. @p writer gets the open stream.
   */
  template <typename Writer>
  void
  write_atomically(const std::string &filename, const Writer &writer)
  {
    const std::string temporary = filename + ".part";
    {
      std::ofstream out(temporary);
      AssertThrow(out, dealii::ExcMessage("Cannot write <" + temporary + ">."));
      // A writer that fails on the full disk throws its own words (deal.II:
      // "output stream error"); the message says what happened, and the
      // partial file goes either way.
      bool written = false;
      try
      {
        writer(out);
        out.flush();
        written = static_cast<bool>(out);
      }
      catch (...)
      {
      }
      if (!written)
      {
        out.close();
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        AssertThrow(false,
                    dealii::ExcMessage("Cannot write <" + filename +
                                       "> (disk full?)."));
      }
    }
    std::filesystem::rename(temporary, filename);
  }
} // namespace tribos

#endif
