#ifndef tribos_core_model_checks_h
#define tribos_core_model_checks_h

#include <tribos/core/warnings.h>
#include <tribos/parameters/all_parameters.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/tria.h>

#include <string>

namespace tribos
{
  using namespace dealii;

  /**
   * @name The checks of a model that are not about one parameter
   *
   * Free functions of the parameters and the mesh: the mesh's size before
   * it is built, what triangles and tetrahedra do not support, and the
   * warnings about the model's support. They hold no state, so the setup
   * calls them where it needs them.
   * @{
   */

  /** The memory of the machines the processes of @p communicator run on
   * (collective). */
  double
  machines_memory(const MPI_Comm communicator);

  /** The address space the processes of @p communicator may still map
   * under their limit (RLIMIT_AS, ulimit -v: a batch system's or a test's),
   * as if each had the least any has left; infinite without a limit
   * (collective). Linux: what a process has mapped is read from
   * /proc/self/statm. */
  double
  address_space_left(const MPI_Comm communicator);

  /** The memory a mesh built now may take: the machines' memory, or the
   * address space left if less (collective). */
  double
  run_memory(const MPI_Comm communicator);

  /** The bytes a mesh takes per active cell with its dofs, matrix and
   * solver (measured: see check_mesh_size()), for cells of Polynomial
   * degree @p degree in @p dim dimensions. */
  double
  bytes_per_cell(const unsigned int dim, const unsigned int degree);

  /** Refuse a Scene/Refinement whose mesh would not fit in @p memory:
   * the scene's @p n_scene_cells unrefined cells times 2^(dim level). */
  template <int dim>
  void
  check_mesh_size(const Parameters::AllParameters &parameters,
                  const unsigned int               n_scene_cells,
                  const double                     memory);

  /**
   * The most active cells an adaptive mesh (Adaptivity) with
   * @p n_cells cells now may be refined to: as many as the machines'
   * memory holds, and no more than the address space left takes on top
   * of the present cells (address_space_left()), at the bytes per cell
   * of bytes_per_cell() times adaptive_memory_factor. The estimate that
   * refuses a Scene/Refinement, so that Adaptivity needs no Maximum dofs
   * to stay within the memory (Maximum level 20 with Refine fraction 0.98
   * took 6 GB in 3 minutes). Collective.
   */
  template <int dim>
  double
  adaptive_cell_limit(const Parameters::AllParameters &parameters,
                      const double                     n_cells,
                      const MPI_Comm                   communicator);

  /** The bytes per cell of an adapted mesh over bytes_per_cell(): its
   * parents, its constraints, an adaptation's transfer, and the margin
   * the measurements ask for (model_checks.cc). */
  constexpr double adaptive_memory_factor = 2;

  /** Refuse what simplex meshes do not support (mixed cell kinds, F-bar,
   * lumped mass on quadratic simplices); warn of locking. */
  template <int dim>
  void
  check_simplex_model(const Parameters::AllParameters &parameters,
                      const Triangulation<dim>        &triangulation,
                      Warnings                        &warnings);

  /**
   * The warning that nothing in @p parameters loads the model (no Neumann
   * load, no body force, no Dirichlet value other than 0, no moving rigid
   * surface, no dynamics), or an empty string where something does.
   */
  std::string
  nothing_loads_warning(const Parameters::AllParameters &parameters);

  /**
   * Warnings about the model's support: nothing loads it (without contact
   * pairs: with them, bodies meshed overlapping are loaded by their
   * contact, which only the run shows; Simulation warns at its end if no
   * contact force exceeds round-off), or a body that nothing holds
   * (statics). Collective over the mesh's communicator.
   */
  template <int dim>
  void
  support_warnings(const Parameters::AllParameters &parameters,
                   const Triangulation<dim>        &triangulation,
                   Warnings                        &warnings);

  /** @} */
} // namespace tribos

#endif
