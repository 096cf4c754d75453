#ifndef tribos_base_fork_server_h
#define tribos_base_fork_server_h

#include <optional>
#include <vector>

namespace tribos
{
  /**
   * `tribos --fork-server`: many short runs, each in a process of its own,
   * without paying each time for the program's start.
   *
   * Loading tribos takes about half a second on the machines it is tested
   * on: the dynamic linker binds some 340 000 symbols of the 200 shared
   * libraries deal.II brings (Trilinos, PETSc, MPI, ...). The test suite
   * starts about a thousand short runs, most of which compute for a tenth
   * of a second, so that start was most of its time. The server is
   * started once, loads the libraries once, and forks a child for each
   * run it is asked for: the child goes on into main() with the run's
   * command line, exactly as a process started from the shell would (the
   * same code, MPI initialized in the child as a singleton, its own output
   * streams and exit status), at the cost of a fork.
   *
   * The requests come on standard input, one after the other, as lines:
   *
   *   run N              the run's command line has N arguments
   *   <directory>        its working directory
   *   <stdout file>      where its standard output goes
   *   <stderr file>      where its standard error goes
   *   M                  the number of environment variables that follow
   *   <NAME=value> x M   its whole environment
   *   <argument> x N     its arguments (without the program's name)
   *
   * The server itself runs nothing but this loop: no MPI, no threads of
   * its own. The one thread a library starts as it loads (OpenBLAS's
   * pool) is stopped before each fork by the library's pthread_atfork
   * handler and started again in the child at its first use.
   *
   * For each, the server waits for the child and answers on standard
   * output with one line, "exit <status>" or "signal <number>". It ends at
   * the end of its input. Used by the test drivers
   * (tests/tribos_testing/__init__.py, run()); not meant for users, who
   * start one run per process.
   */
  class ForkServer
  {
  public:
    /**
     * Serve requests until the end of standard input. Returns nothing in
     * the server, which then ends; in each child, returns the run's
     * argument vector (the program name first, null-terminated, valid
     * until the process ends), with the child's directory, output streams
     * and environment already set.
     */
    static std::optional<std::vector<char *>>
    serve(const char *program_name);
  };
} // namespace tribos

#endif
