/**
 * tribos: multi-body contact with Coulomb friction at finite strain.
 *
 * Command line:
 *   tribos FILE.prm [--set "Section/Entry=value"]... [--restart DIR]
 *   tribos --print-parameters [prm|json]
 *   tribos --help
 */

#include <tribos/base/exceptions.h>
#include <tribos/core/problem.h>
#include <tribos/parameters/all_parameters.h>

#include <deal.II/base/mpi.h>

#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>
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

  template <int dim>
  void
  run(dealii::ParameterHandler &prm,
      const std::string        &filename,
      const std::string        &restart)
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
      // Let the problem (and its TimerOutput) be destroyed before a failure
      // propagates, so that its destructor runs outside of stack unwinding.
      std::exception_ptr failure;
      bool               again = false;
      {
        tribos::Problem<dim> problem(parameters, MPI_COMM_WORLD);
        problem.set_rebalance(rebalance);
        try
        {
          problem.run();
        }
        catch (tribos::Rebalance &next)
        {
          rebalance = std::move(next);
          again     = true;
        }
        catch (...)
        {
          failure = std::current_exception();
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
   * A run that mpirun did not start is an MPI singleton. Open MPI then
   * starts a helper daemon and probes every network transport (0.3 s of
   * MPI_Init and MPI_Finalize, half of a small run): a singleton needs
   * neither, so it is told so, unless the user set these variables.
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
  }
} // namespace



int
main(int argc, char **argv)
{
  using namespace dealii;
  configure_singleton_mpi();
  // Threads for the assembly: the node's cores divided among its MPI
  // processes (DEAL_II_NUM_THREADS sets fewer).
  Utilities::MPI::MPI_InitFinalize mpi(argc,
                                       argv,
                                       numbers::invalid_unsigned_int);
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

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
      run<2>(prm, filename, restart);
    else
      run<3>(prm, filename, restart);
  }
  catch (const tribos::NonConvergence &failure)
  {
    if (root)
      std::cerr << "\ntribos: NO CONVERGENCE: " << failure.what() << std::endl;
    return 2;
  }
  catch (const dealii::ExceptionBase &error)
  {
    if (root)
    {
      std::cerr << "\ntribos: ERROR: ";
      error.print_info(std::cerr);
      std::cerr << std::endl;
    }
    return 1;
  }
  catch (const std::exception &error)
  {
    if (root)
      std::cerr << "\ntribos: ERROR: " << error.what() << std::endl;
    return 1;
  }
  return 0;
}
