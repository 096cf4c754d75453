#include <tribos/base/directory_lock.h>

#include <deal.II/base/exceptions.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace tribos
{
  DirectoryLock::DirectoryLock(const std::string &directory,
                               const std::string &entry)
  {
    const std::string path = directory + "/.tribos.lock";
    descriptor = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    AssertThrow(descriptor >= 0,
                dealii::ExcMessage("Parameter <" + entry + "> = <" + directory +
                                   ">: cannot create the lock "
                                   "file <" +
                                   path + "> (" + std::strerror(errno) + ")."));
    if (::flock(descriptor, LOCK_EX | LOCK_NB) != 0)
    {
      char          holder[64] = {};
      const ssize_t n = ::pread(descriptor, holder, sizeof(holder) - 1, 0);
      ::close(descriptor);
      descriptor      = -1;
      std::string who = n > 0 ? std::string(holder, n) : std::string();
      while (!who.empty() && (who.back() == '\n' || who.back() == ' '))
        who.pop_back();
      AssertThrow(false,
                  dealii::ExcMessage(
                    "Parameter <" + entry + "> = <" + directory +
                    ">: another tribos run writes there" +
                    (who.empty() ? std::string() : " (process " + who + ")") +
                    ". Give this run another directory, or wait until that "
                    "one ends."));
    }
    const std::string me = std::to_string(::getpid()) + "\n";
    if (::ftruncate(descriptor, 0) == 0)
      (void)!::pwrite(descriptor, me.data(), me.size(), 0);
  }



  DirectoryLock::~DirectoryLock()
  {
    if (descriptor >= 0)
      ::close(descriptor);
  }
} // namespace tribos
