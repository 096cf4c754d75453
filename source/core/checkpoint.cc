#include <tribos/core/checkpoint.h>

#include <deal.II/base/exceptions.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace tribos
{
  namespace
  {
    const char *const magic = "tribos checkpoint";

    /** FNV-1a, 64 bits: any change of a byte changes it. */
    std::uint64_t
    checksum(const std::string &bytes)
    {
      std::uint64_t hash = 14695981039346656037ull;
      for (const char c : bytes)
      {
        hash ^= static_cast<unsigned char>(c);
        hash *= 1099511628211ull;
      }
      return hash;
    }
  } // namespace



  void
  Checkpoint::save(const std::string &directory) const
  {
    namespace fs = std::filesystem;
    const fs::path target(directory);
    const fs::path temporary = target.string() + ".part";
    fs::remove_all(temporary);
    fs::create_directories(temporary);
    // A failed write (a full disk) leaves no partial checkpoint behind.
    try
    {
      std::ofstream out(temporary / "state.bin", std::ios::binary);
      AssertThrow(out,
                  dealii::ExcMessage("Cannot write the checkpoint <" +
                                     (temporary / "state.bin").string() +
                                     ">."));
      {
        std::ostringstream payload;
        {
          boost::archive::binary_oarchive archive(payload);
          archive << *this;
        }
        const std::string               bytes = payload.str();
        boost::archive::binary_oarchive archive(out);
        const std::string               header  = magic;
        const unsigned int              version = format;
        const std::uint64_t             sum     = checksum(bytes);
        archive << header << version << sum << bytes;
      }
      out.flush();
      AssertThrow(out,
                  dealii::ExcMessage("Cannot write the checkpoint <" +
                                     (temporary / "state.bin").string() +
                                     "> (disk full?)."));
    }
    catch (...)
    {
      std::error_code ignored;
      fs::remove_all(temporary, ignored);
      AssertThrow(false,
                  dealii::ExcMessage("Cannot write the checkpoint <" +
                                     target.string() + "> (disk full?)."));
    }
    // The old checkpoint goes only once the new one is complete.
    const fs::path old = target.string() + ".old";
    fs::remove_all(old);
    if (fs::exists(target))
      fs::rename(target, old);
    fs::rename(temporary, target);
    fs::remove_all(old);
  }



  void
  Checkpoint::load(const std::string &directory)
  {
    const std::string file = directory + "/state.bin";
    std::ifstream     in(file, std::ios::binary);
    AssertThrow(in,
                dealii::ExcMessage("--restart <" + directory +
                                   ">: no checkpoint there (" + file +
                                   " cannot be read). Give the directory "
                                   "<Output/Directory>/checkpoint of a run "
                                   "with Output/Checkpoint every > 0."));
    std::string  header;
    unsigned int version = 0;
    try
    {
      boost::archive::binary_iarchive archive(in);
      archive >> header >> version;
      if (header != magic || version != format)
        throw std::runtime_error("not a tribos checkpoint of format " +
                                 std::to_string(format));
      std::uint64_t sum = 0;
      std::string   bytes;
      archive >> sum >> bytes;
      if (sum != checksum(bytes))
        throw std::runtime_error("its checksum does not match its contents: "
                                 "the file changed after it was written");
      std::istringstream              payload(bytes);
      boost::archive::binary_iarchive state(payload);
      state >> *this;
    }
    catch (const std::exception &e)
    {
      // A message of its own: the text of a deal.II exception would carry
      // its stack trace into the user's error.
      std::ostringstream reason;
      if (const auto *deal_ii = dynamic_cast<const dealii::ExceptionBase *>(&e))
        deal_ii->print_info(reason);
      else
        reason << e.what();
      throw dealii::ExcMessage("--restart <" + directory + ">: " + file +
                               " is not a readable tribos checkpoint (" +
                               reason.str() + ").");
    }
  }
} // namespace tribos
