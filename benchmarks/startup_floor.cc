/**
 * Benchmark: the floor under tribos' process start. This program is
 * linked as tribos is (tribos_core, deal.II and the two hundred shared
 * libraries deal.II needs) and returns at once, so its wall time is what
 * the kernel and the dynamic loader spend mapping and relocating those
 * libraries before main() runs. benchmarks/solver_speed.py times it beside
 * `tribos --help`; the difference is tribos' own start (MPI_Init, the
 * command line).
 *
 *   ./build/benchmarks/startup_floor
 */

#include <tribos/parameters/all_parameters.h>

#include <deal.II/base/parameter_handler.h>

int
main(int argc, char **)
{
  // Not taken when timed; the call keeps tribos_core and deal.II among
  // the libraries the program needs, whatever the linker's defaults.
  if (argc > 1)
  {
    dealii::ParameterHandler prm;
    tribos::Parameters::AllParameters::declare_parameters(prm);
  }
  return 0;
}
