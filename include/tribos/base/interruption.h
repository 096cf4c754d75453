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
   * of a killed program; or between two stages of the setup, before any
   * output is written (a setup can take minutes: a large mesh, its dofs
   * and matrix), which leaves the output directory as it was.
   */
  class Interrupted : public std::runtime_error
  {
  public:
    /** @p in_setup: thrown between the stages of the setup, before any
     * output (Interruption::check()). */
    explicit Interrupted(const int signal_number, const bool in_setup = false);

    /** The signal's number. */
    int
    signal_number() const
    {
      return number;
    }

    /** Whether the run stopped in its setup, before any output. */
    bool
    in_setup() const
    {
      return setup;
    }

    /** Its name (SIGTERM, SIGINT). */
    static std::string
    name(const int signal_number);

  private:
    int  number;
    bool setup;
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

    /**
     * Throws Interrupted where a signal arrived on any process of
     * @p communicator (collective: a run stops on every process at the
     * same iteration). Also between two stages of the first setup
     * (@p in_setup): a signal that arrived while the mesh, the dofs or the
     * materials were built stops the run there, with nothing written, and
     * not only at the first Newton iteration, which a setup that outgrows
     * the memory never reaches (a single SIGTERM, as timeout sends, was
     * ignored).
     */
    void
    check(const MPI_Comm communicator, const bool in_setup = false);
  } // namespace Interruption
} // namespace tribos

#endif
