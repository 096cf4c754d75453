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

  /** Refuse a Scene/Refinement whose mesh would not fit in @p memory:
   * the scene's @p n_scene_cells unrefined cells times 2^(dim level). */
  template <int dim>
  void
  check_mesh_size(const Parameters::AllParameters &parameters,
                  const unsigned int               n_scene_cells,
                  const double                     memory);

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
