#ifndef tribos_base_directory_lock_h
#define tribos_base_directory_lock_h

#include <string>

namespace tribos
{
  /**
   * One run per output directory: an advisory lock (flock) on
   * <directory>/.tribos.lock for the life of this object. The kernel drops
   * it when the process ends however it ends, so a killed run leaves no
   * stale lock; a second run that finds the lock held is refused with the
   * holder's process id (two runs writing one directory spliced their
   * history.csv rows and both exited 0).
   */
  class DirectoryLock
  {
  public:
    /** Lock @p directory (which must exist) or throw, naming @p entry
     * (the parameter that gave the directory) and the other run. */
    DirectoryLock(const std::string &directory, const std::string &entry);
    ~DirectoryLock();

    DirectoryLock(const DirectoryLock &) = delete;
    DirectoryLock &
    operator=(const DirectoryLock &) = delete;

  private:
    int descriptor = -1;
  };
} // namespace tribos

#endif
