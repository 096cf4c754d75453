#ifndef tribos_core_warnings_h
#define tribos_core_warnings_h

#include <deal.II/base/mpi.h>

#include <string>
#include <vector>

namespace tribos
{
  /**
   * The warnings of one run, for the user: each is printed on the first
   * process when it is found ("tribos: WARNING: ..." on std::cerr) and kept
   * for summary.txt in the order found. One object per run, handed to the
   * parts that check the model (setup, mesh, contact, rebalancing), so that
   * none of them needs the Problem to warn.
   */
  class Warnings
  {
  public:
    explicit Warnings(const MPI_Comm communicator);

    /** Print @p message (first process) and keep it. */
    void
    warn(const std::string &message);

    /** Every warning so far, in the order found. */
    const std::vector<std::string> &
    list() const;

  private:
    MPI_Comm                 communicator;
    std::vector<std::string> messages;
  };
} // namespace tribos

#endif
