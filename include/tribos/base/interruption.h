#ifndef tribos_base_interruption_h
#define tribos_base_interruption_h

#include <mpi.h>

#include <stdexcept>
#include <string>

namespace tribos
{
  /**
   * A run stopped by SIGTERM or SIGINT: thrown between Newton iterations,
   * so that every file written so far is whole, the summary says so and
   * the process exits with 128 + the signal's number, as the shell expects
   * of a killed program.
   */
  class Interrupted : public std::runtime_error
  {
  public:
    explicit Interrupted(const int signal_number);

    /** The signal's number. */
    int
    signal_number() const
    {
      return number;
    }

    /** Its name (SIGTERM, SIGINT). */
    static std::string
    name(const int signal_number);

  private:
    int number;
  };



  namespace Interruption
  {
    /**
     * Catch SIGTERM and SIGINT: the first one is only noted (the run
     * stops at its next Newton iteration); a second one of the same kind
     * ends the process at once (the default action). SIGPIPE is
     * ignored: a console piped into a program that closed it does not end
     * the run.
     */
    void
    install();

    /** Throws Interrupted where a signal arrived on any process of
     * @p communicator (collective: a run stops on every process at the
     * same iteration). */
    void
    check(const MPI_Comm communicator);
  } // namespace Interruption
} // namespace tribos

#endif
