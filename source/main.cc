/**
 * tribos: multi-body contact with Coulomb friction at finite strain.
 *
 * Command line:
 *   tribos FILE.prm [--set "Section/Entry=value"]... [--restart DIR]
 *   tribos --print-parameters [prm|json]
 *   tribos --help
 */

#include <tribos/base/exceptions.h>
#include <tribos/base/fork_server.h>
#include <tribos/base/interruption.h>
#include <tribos/parameters/all_parameters.h>
#include <tribos/run/simulation.h>

#include <deal.II/base/mpi.h>

#include <chrono>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace
{
  void
  print_help()
  {
    std::cout
      << "tribos - finite element contact with Coulomb friction (deal.II)\n\n"
         "Usage:\n"
         "  tribos FILE.prm [--set \"Section/Entry=value\"]...\n"
         "      Run the scene described by FILE.prm. Each --set overrides one\n"
         "      entry of the file (subsections separated by '/'); unknown\n"
         "      entries and values outside the allowed ones are errors.\n"
         "  tribos FILE.prm [--set ...]... --restart DIR\n"
         "      Go on from the checkpoint in DIR (Output/Checkpoint every\n"
         "      of an earlier run of the same FILE.prm and mesh), with any\n"
         "      number of MPI processes.\n"
         "  tribos --print-parameters [prm|json]\n"
         "      Print every parameter with its documentation, default and\n"
         "      allowed values.\n"
         "  tribos --help\n"
         "      This text.\n\n"
         "Run in parallel with: mpirun -np N tribos FILE.prm\n"
         "Exit status: 0 success, 1 bad input or error, 2 no convergence.\n";
  }

  /** The exit status and the message of a failure. */
  std::pair<int, std::string>
  describe(const std::exception_ptr &failure)
  {
    try
    {
      std::rethrow_exception(failure);
    }
    catch (const tribos::NonConvergence &error)
    {
      return {2, std::string("NO CONVERGENCE: ") + error.what()};
    }
    catch (const tribos::Interrupted &signal)
    {
      return {128 + signal.signal_number(),
              std::string("INTERRUPTED: ") + signal.what() +
                (signal.in_setup() ?
                   "; nothing was written (the output directory is as it "
                   "was)" :
                   "; summary.txt says so, outputs of the converged steps "
                   "are kept")};
    }
    catch (const dealii::ExceptionBase &error)
    {
      std::ostringstream message;
      error.print_info(message);
      return {1, "ERROR: " + message.str()};
    }
    catch (const std::exception &error)
    {
      return {1, std::string("ERROR: ") + error.what()};
    }
    catch (...)
    {
      return {1, "ERROR: unknown exception"};
    }
  }



  /**
   * Makes sure that a failure ends the run under MPI, without a hang.
   *
   * Most failures are raised on every process alike (bad input, a
   * non-convergence the processes agreed on); the first process then
   * prints the message and every process returns the exit status. A
   * failure raised on some processes only (a file one of them cannot
   * write) would leave the others waiting in their next collective step,
   * and the failed ones too in the collective steps of the problem's
   * destructor, with the message unprinted if the first process is not
   * among them. So a process that failed first meets the others on a
   * barrier of a communicator of its own (the others may be inside a
   * collective step on MPI_COMM_WORLD), before anything is destroyed: if
   * not every process arrives within a few seconds, it prints its message
   * itself and aborts the run with the failure's exit status.
   */
  class FailureHandshake
  {
  public:
    FailureHandshake()
    {
      MPI_Comm_dup(MPI_COMM_WORLD, &communicator);
    }

    ~FailureHandshake()
    {
      MPI_Comm_free(&communicator);
    }

    /** Returns if every process failed too; aborts the run otherwise. */
    void
    meet(const std::exception_ptr &failure)
    {
      if (met)
        return;
      met             = true;
      int rank        = 0;
      int n_processes = 1;
      MPI_Comm_rank(communicator, &rank);
      MPI_Comm_size(communicator, &n_processes);
      if (n_processes == 1)
        return;
      MPI_Request request;
      MPI_Ibarrier(communicator, &request);
      int        everyone = 0;
      const auto start    = std::chrono::steady_clock::now();
      while (!everyone && std::chrono::steady_clock::now() - start <
                            std::chrono::seconds(wait_seconds))
      {
        MPI_Test(&request, &everyone, MPI_STATUS_IGNORE);
        if (!everyone)
          std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      if (everyone)
        return;
      const auto [status, message] = describe(failure);
      std::cerr << "\ntribos: " << message << "\n(on process " << rank << " of "
                << n_processes << " only: the others had not failed within "
                << wait_seconds << " s; aborting the run)" << std::endl;
      MPI_Abort(MPI_COMM_WORLD, status);
    }

  private:
    /** Long enough for processes that fail together to meet. */
    static constexpr int wait_seconds = 10;
    MPI_Comm             communicator;
    bool                 met = false;
  };



  template <int dim>
  void
  run(dealii::ParameterHandler &prm,
      const std::string        &filename,
      const std::string        &restart,
      FailureHandshake         &handshake)
  {
    tribos::Parameters::AllParameters parameters;
    parameters.parse_parameters(prm);
    parameters.input_warnings =
      tribos::Parameters::input_file_warnings(filename);
    parameters.restart_directory = restart;
    // A rebalance (Parallel/Rebalance threshold) ends a problem after a
    // step and the next one goes on from its state, partitioned anew.
    tribos::Rebalance rebalance;
    for (;;)
    {
      // Let the simulation (and its TimerOutput) be destroyed before a
      // failure propagates, so that its destructor runs outside of stack
      // unwinding.
      std::exception_ptr failure;
      bool               again = false;
      {
        tribos::Simulation<dim> simulation(parameters,
                                           MPI_COMM_WORLD,
                                           rebalance);
        try
        {
          simulation.run();
        }
        catch (tribos::Rebalance &next)
        {
          rebalance = std::move(next);
          again     = true;
        }
        catch (...)
        {
          failure = std::current_exception();
          handshake.meet(failure);
        }
      }
      if (failure)
        std::rethrow_exception(failure);
      if (!again)
        return;
      parameters.restart_directory = rebalance.checkpoint;
    }
  }
} // namespace



namespace
{
  /**
   * The session directory of an MPI singleton: Open MPI's default is one
   * per user and host under the temporary directory, created by whichever
   * process gets there first, and singletons started at the same moment
   * (ctest -j2, a parameter sweep) raced on it: "A call to mkdir was unable
   * to create the desired directory ... File exists", and the run died in
   * MPI_Init. Each singleton gets a directory of its own, removed when the
   * program ends (after MPI_Finalize: this object is static).
   */
  class SingletonSessionDirectory
  {
  public:
    /** Create the directory and point Open MPI at it (unless the user set
     * OMPI_MCA_orte_tmpdir_base). */
    void
    create()
    {
      if (std::getenv("OMPI_MCA_orte_tmpdir_base") != nullptr)
        return;
      const char *tmp = std::getenv("TMPDIR");
      std::string name =
        std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") +
        "/tribos-mpi-XXXXXX";
      std::vector<char> buffer(name.begin(), name.end());
      buffer.push_back('\0');
      if (mkdtemp(buffer.data()) == nullptr)
        return;
      directory = buffer.data();
      setenv("OMPI_MCA_orte_tmpdir_base", directory.c_str(), 1);
    }

    ~SingletonSessionDirectory()
    {
      if (!directory.empty())
      {
        std::error_code ignored;
        std::filesystem::remove_all(directory, ignored);
      }
    }

  private:
    std::string directory;
  };



  /**
   * A run that mpirun did not start is an MPI singleton. Open MPI then
   * starts a helper daemon and probes every network transport (0.3 s of
   * MPI_Init and MPI_Finalize, half of a small run): a singleton needs
   * neither, so it is told so, unless the user set these variables; and
   * it gets a session directory of its own.
   */
  void
  configure_singleton_mpi()
  {
    const bool launched = std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr ||
                          std::getenv("PMIX_RANK") != nullptr ||
                          std::getenv("PMI_RANK") != nullptr;
    if (launched)
      return;
    setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
    setenv("OMPI_MCA_pml", "ob1", 0);
    setenv("OMPI_MCA_btl", "self,vader", 0);
    static SingletonSessionDirectory session;
    session.create();
  }
} // namespace



int
main(int argc, char **argv)
{
  using namespace dealii;
  // The test drivers' server of short runs (base/fork_server.h): the
  // server ends here; each of its children goes on with its run's
  // command line.
  if (argc == 2 && std::string(argv[1]) == "--fork-server")
  {
    static auto served = tribos::ForkServer::serve(argv[0]);
    if (!served)
      return 0;
    argc = static_cast<int>(served->size()) - 1;
    argv = served->data();
  }
  configure_singleton_mpi();
  // Threads for the assembly: the node's cores divided among its MPI
  // processes (DEAL_II_NUM_THREADS sets fewer).
  Utilities::MPI::MPI_InitFinalize mpi(argc,
                                       argv,
                                       numbers::invalid_unsigned_int);
  const bool       root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  FailureHandshake handshake;
  // SIGTERM and SIGINT stop the run between Newton iterations with a
  // summary, or between the stages of its setup before any output (after
  // MPI's start, which may install handlers of its own).
  tribos::Interruption::install();

  try
  {
    std::string              filename;
    std::vector<std::string> overrides;
    std::string              print_format;
    std::string              restart;
    bool                     print = false;

    for (int i = 1; i < argc; ++i)
    {
      const std::string argument = argv[i];
      if (argument == "--help" || argument == "-h")
      {
        if (root)
          print_help();
        return 0;
      }
      else if (argument == "--set")
      {
        AssertThrow(i + 1 < argc,
                    ExcMessage("--set needs an argument "
                               "\"Section/Entry=value\"."));
        overrides.emplace_back(argv[++i]);
      }
      else if (argument.rfind("--set=", 0) == 0)
        overrides.push_back(argument.substr(6));
      else if (argument == "--restart")
      {
        AssertThrow(i + 1 < argc,
                    ExcMessage("--restart needs the checkpoint directory "
                               "(<Output/Directory>/checkpoint of the run "
                               "that wrote it)."));
        restart = argv[++i];
      }
      else if (argument == "--print-parameters")
      {
        print        = true;
        print_format = "prm";
        if (i + 1 < argc && argv[i + 1][0] != '-')
          print_format = argv[++i];
        AssertThrow(print_format == "prm" || print_format == "json",
                    ExcMessage("--print-parameters: unknown format <" +
                               print_format + ">. Allowed: prm, json."));
      }
      else if (!argument.empty() && argument[0] == '-')
      {
        AssertThrow(false,
                    ExcMessage("Unknown option <" + argument +
                               ">. See tribos --help."));
      }
      else
      {
        AssertThrow(filename.empty(),
                    ExcMessage("More than one parameter file given (<" +
                               filename + "> and <" + argument + ">)."));
        filename = argument;
      }
    }

    ParameterHandler prm;
    tribos::Parameters::AllParameters::declare_parameters(prm);

    if (print)
    {
      if (root && print_format == "json")
        prm.print_parameters(std::cout, ParameterHandler::JSON);
      else if (root)
        tribos::Parameters::print_documented_parameters(prm, std::cout);
      return 0;
    }

    AssertThrow(!filename.empty(),
                ExcMessage("No parameter file given. Usage: tribos "
                           "FILE.prm [--set \"Section/Entry=value\"]... "
                           "(see tribos --help)."));

    const unsigned int dim =
      tribos::Parameters::read_dimension(filename, overrides);
    tribos::Parameters::read_input(prm, filename, overrides);
    if (dim == 2)
      run<2>(prm, filename, restart, handshake);
    else
      run<3>(prm, filename, restart, handshake);
  }
  catch (...)
  {
    const std::exception_ptr failure = std::current_exception();
    handshake.meet(failure);
    const auto [status, message] = describe(failure);
    if (root)
      std::cerr << "\ntribos: " << message << std::endl;
    return status;
  }
  return 0;
}
