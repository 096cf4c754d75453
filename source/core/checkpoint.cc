#include <tribos/core/checkpoint.h>

#include <deal.II/base/exceptions.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <filesystem>
#include <fstream>

namespace tribos
{
  namespace
  {
    const char *const magic = "tribos checkpoint";
  }



  void
  Checkpoint::save(const std::string &directory) const
  {
    namespace fs = std::filesystem;
    const fs::path target(directory);
    const fs::path temporary = target.string() + ".part";
    fs::remove_all(temporary);
    fs::create_directories(temporary);
    {
      std::ofstream out(temporary / "state.bin", std::ios::binary);
      AssertThrow(out,
                  dealii::ExcMessage("Cannot write the checkpoint <" +
                                     (temporary / "state.bin").string() +
                                     ">."));
      {
        boost::archive::binary_oarchive archive(out);
        const std::string               header  = magic;
        const unsigned int              version = format;
        archive << header << version << *this;
      }
      out.flush();
      AssertThrow(out,
                  dealii::ExcMessage("Cannot write the checkpoint <" +
                                     (temporary / "state.bin").string() +
                                     "> (disk full?)."));
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
      AssertThrow(header == magic && version == format,
                  dealii::ExcMessage("not a tribos checkpoint of format " +
                                     std::to_string(format)));
      archive >> *this;
    }
    catch (const std::exception &e)
    {
      AssertThrow(false,
                  dealii::ExcMessage("--restart <" + directory + ">: " + file +
                                     " is not a readable tribos "
                                     "checkpoint (" +
                                     e.what() + ")."));
    }
  }
} // namespace tribos
