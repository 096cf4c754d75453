/**
 * The checks of a model that are not about one parameter: its mesh's size
 * before it is built, what triangles and tetrahedra do not support, and
 * the warnings about its support (nothing loads it, a body nothing holds).
 */

#include <tribos/base/text.h>
#include <tribos/core/model_checks.h>
#include <tribos/material/material_model.h>
#include <tribos/scene/scene.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>

namespace tribos
{
  namespace
  {
    /** Whether @p expression is a number equal to zero ("0", "0.0",
     * "-0e3"), not an expression that may vanish. */
    bool
    is_zero(const std::string &expression)
    {
      const std::string text  = Text::trim(expression);
      char             *end   = nullptr;
      const double      value = std::strtod(text.c_str(), &end);
      return !text.empty() && end != nullptr && *end == '\0' && value == 0;
    }

    bool
    all_zero(const std::vector<std::string> &expressions)
    {
      return std::all_of(expressions.begin(), expressions.end(), is_zero);
    }
  } // namespace



  std::string
  nothing_loads_warning(const Parameters::AllParameters &parameters)
  {
    const auto &bc     = parameters.boundary_conditions;
    bool        loaded = !bc.neumann.empty() || !bc.body_force.empty() ||
                  parameters.time_stepping.dynamic();
    for (const auto &d : bc.dirichlet)
      loaded = loaded || !all_zero(d.expressions);
    for (const auto &surface : parameters.contact.rigid_surfaces)
      loaded = loaded || !all_zero(surface.motion);
    if (loaded)
      return "";
    return "nothing loads the model: no Neumann load, no body force, no "
           "Dirichlet value other than 0, no moving rigid surface and no "
           "dynamics, so the solution stays the initial state. Check "
           "Boundary conditions and Contact/Rigid surfaces.";
  }



  template <int dim>
  void
  support_warnings(const Parameters::AllParameters &parameters,
                   const Triangulation<dim>        &triangulation,
                   Warnings                        &warnings)
  {
    const MPI_Comm mpi_communicator = triangulation.get_communicator();
    // Nothing loads the model: the answer is the initial state. Unless
    // bodies in contact pairs are meshed overlapping: their contact loads
    // them (a meshed overlap was warned of while its contact force was
    // 12.9). That shows in the run only: Simulation decides at its end.
    const auto &bc = parameters.boundary_conditions;
    if (parameters.contact.pairs.empty())
      if (const std::string w = nothing_loads_warning(parameters); !w.empty())
        warnings.warn(w);

    // A body that neither a Dirichlet condition nor a contact pair touches
    // has rigid-body modes nothing holds (a singular static system).
    if (parameters.time_stepping.dynamic())
      return;
    std::set<unsigned int> held;
    for (const auto &d : bc.dirichlet)
      held.insert(d.boundary_id);
    held.insert(bc.symmetry.begin(), bc.symmetry.end());
    // The bodies each boundary id lies on (every process's).
    std::set<std::pair<unsigned int, unsigned int>> local_ids;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            local_ids.insert(
              {cell->face(f)->boundary_id(), cell->material_id()});
    std::vector<unsigned int> id_and_body;
    for (const auto &[id, body] : local_ids)
    {
      id_and_body.push_back(id);
      id_and_body.push_back(body);
    }
    std::map<unsigned int, std::set<unsigned int>> bodies_of_id;
    for (const auto &part :
         Utilities::MPI::all_gather(mpi_communicator, id_and_body))
      for (unsigned int i = 0; i + 1 < part.size(); i += 2)
        bodies_of_id[part[i]].insert(part[i + 1]);
    for (const auto &pair : parameters.contact.pairs)
    {
      // A surface in contact with itself holds no rigid-body motion,
      // unless it spans several bodies: then it is their contact with
      // each other, as a pair of two surfaces is.
      if (pair.self_contact())
      {
        std::set<unsigned int> spanned;
        for (const auto id : pair.slave_boundary)
          spanned.insert(bodies_of_id[id].begin(), bodies_of_id[id].end());
        if (spanned.size() < 2)
          continue;
      }
      held.insert(pair.slave_boundary.begin(), pair.slave_boundary.end());
      held.insert(pair.master_boundary.begin(), pair.master_boundary.end());
    }
    std::set<unsigned int> bodies, touched;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        bodies.insert(cell->material_id());
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              held.count(cell->face(f)->boundary_id()) > 0)
            touched.insert(cell->material_id());
      }
    bodies  = Utilities::MPI::compute_set_union(bodies, mpi_communicator);
    touched = Utilities::MPI::compute_set_union(touched, mpi_communicator);
    for (const auto body : bodies)
      if (touched.count(body) == 0)
        warnings.warn(
          "body " + std::to_string(body) +
          " has no Dirichlet or symmetry condition and no contact "
          "surface: nothing holds its rigid-body motion (a singular "
          "static system). Add a support or a contact pair, or "
          "Nonlinear solver/Stabilization factor.");
  }



  double
  address_space_left(const MPI_Comm mpi_communicator)
  {
    double left = std::numeric_limits<double>::infinity();
    rlimit limit;
    if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    {
      // The first number of statm: the pages mapped (the libraries, MPI's
      // buffers, the heap).
      double        pages = 0;
      std::ifstream statm("/proc/self/statm");
      statm >> pages;
      // And what the threads may map without a byte of data: glibc gives
      // each thread that allocates an arena of 64 MB of address space, and
      // the assembly's threads start theirs when the mesh first grows
      // large enough to be shared among them (measured, 2 threads: 136 MB
      // more between 1 254 and 4 944 cells). Counted even once they exist:
      // on the safe side.
      const double arenas = (64 << 20) * double(MultithreadInfo::n_threads());
      left                = std::max(0.,
                      double(limit.rlim_cur) -
                        pages * double(sysconf(_SC_PAGE_SIZE)) - arenas);
    }
    return Utilities::MPI::min(left, mpi_communicator) *
           Utilities::MPI::n_mpi_processes(mpi_communicator);
  }



  double
  run_memory(const MPI_Comm mpi_communicator)
  {
    // Both collective: every process calls both.
    const double machines = machines_memory(mpi_communicator);
    return std::min(machines, address_space_left(mpi_communicator));
  }



  double
  bytes_per_cell(const unsigned int dim, const unsigned int degree)
  {
    return (dim == 2 ? 5e3 : 50e3) * std::pow(double(degree), dim);
  }



  double
  machines_memory(const MPI_Comm mpi_communicator)
  {
    char name[MPI_MAX_PROCESSOR_NAME];
    int  length = 0;
    MPI_Get_processor_name(name, &length);
    const auto hosts =
      Utilities::MPI::all_gather(mpi_communicator, std::string(name, length));
    const std::set<std::string> machines(hosts.begin(), hosts.end());
    return double(sysconf(_SC_PHYS_PAGES)) * sysconf(_SC_PAGE_SIZE) *
           machines.size();
  }



  /**
   * Refuse a Scene/Refinement whose mesh could not fit in memory, before
   * it is built (refinement 10 of the 3D blocks ran a minute in silence
   * and then ended in std::bad_alloc). Each level multiplies its cells by
   * 2^dim. The bytes per cell are measured, one process with the direct solver,
   * on the 3D blocks (17408 Q1 cells: 0.69 GB, 40 kB per cell) and rounded up;
   * they grow with the element's nodes, degree^dim. The limit is the memory of
   * the machines the processes run on.
   */
  template <int dim>
  void
  check_mesh_size(const Parameters::AllParameters &parameters,
                  const unsigned int               n_scene_cells,
                  const double                     memory)
  {
    const unsigned int refinement = parameters.scene.refinement;
    const unsigned int degree     = parameters.finite_element.degree;
    const double n_cells  = n_scene_cells * std::pow(2.0, dim * refinement);
    const double per_cell = bytes_per_cell(dim, degree);
    const double bytes    = n_cells * per_cell;
    if (bytes <= memory)
      return;
    unsigned int largest = 0;
    while (largest < refinement &&
           n_scene_cells * std::pow(2.0, dim * (largest + 1)) * per_cell <=
             memory)
      ++largest;
    std::ostringstream text;
    text.precision(2);
    text << "Parameter <Scene/Refinement> = " << refinement
         << ": the mesh would have about " << n_cells
         << " cells and need about " << bytes / 1e9
         << " GB (an estimate: " << per_cell / 1e3 << " kB per cell of degree "
         << degree << " in " << dim << "D), more than the " << memory / 1e9
         << " GB of memory of this run (its machines', or the address "
            "space its processes have left under their limit). Allowed for "
            "this scene here: at most "
         << largest << ".";
    AssertThrow(false, ExcMessage(text.str()));
  }



  /**
   * The factor adaptive_memory_factor: an adapted mesh holds its parents
   * (a third more cells in 2D, a seventh in 3D) and hanging-node
   * constraints, and an adaptation builds the new pattern and matrix while
   * the old mesh's data are transferred. Measured (Q1, direct solver,
   * resident memory over a 32-cell run's): the sliding block adapted to
   * 30 101 cells 7.8 kB per cell (refined uniformly to 32 768: 7.5 kB),
   * the run 7 kB at 832 262 cells, in 3D 66 kB at 8 080 cells;
   * a refinement of the stretch from 4 944 to 19 488 cells needed more
   * than 6.6 kB per cell of address space beyond the threads' arenas. The
   * estimate of check_mesh_size() (5 kB, 50 kB) is 1.3 to 1.6 times
   * short of these; twice it keeps the limit on the safe side.
   */
  template <int dim>
  double
  adaptive_cell_limit(const Parameters::AllParameters &parameters,
                      const double                     n_cells,
                      const MPI_Comm                   communicator)
  {
    const double per_cell =
      adaptive_memory_factor *
      bytes_per_cell(dim, parameters.finite_element.degree);
    const double machines = machines_memory(communicator);
    const double left     = address_space_left(communicator);
    return std::min(machines / per_cell, n_cells + left / per_cell);
  }



  template <int dim>
  void
  check_simplex_model(const Parameters::AllParameters &parameters,
                      const Triangulation<dim>        &triangulation,
                      Warnings                        &warnings)
  {
    AssertThrow(triangulation.all_reference_cells_are_simplex(),
                ExcMessage(parameters.scene.geometry->mesh_source() +
                           ": the mesh mixes simplices with quadrilaterals "
                           "or hexahedra; tribos takes one kind of cell per "
                           "mesh."));
    AssertThrow(!parameters.finite_element.f_bar,
                ExcMessage("Parameter <Finite element/F-bar> = true: F-bar "
                           "is the remedy of Q1 cells. On triangles and "
                           "tetrahedra use Polynomial degree = 2 against "
                           "locking (P1 locks in isochoric plastic flow)."));
    // Row sums of the P2 simplex mass matrix put no (triangles) or negative
    // (tetrahedra) mass on the vertices.
    AssertThrow(parameters.finite_element.degree == 1 ||
                  !parameters.time_stepping.dynamic() ||
                  parameters.time_stepping.mass_matrix !=
                    Parameters::MassMatrix::lumped,
                ExcMessage("Parameter <Time stepping/Mass matrix> = lumped "
                           "on quadratic triangles or tetrahedra: the row "
                           "sums give the vertices zero or negative mass. "
                           "Use consistent, or Polynomial degree = 1."));
    // The first listed model that locks (of any body id, present or not).
    if (parameters.finite_element.degree == 1)
      for (const std::string &model : parameters.materials.models)
        if (parameters.materials.model(model)->locks_on_linear_simplices())
        {
          warnings.warn("Materials/Model = " + model +
                        " on linear triangles or tetrahedra (Finite "
                        "element/Polynomial degree = 1): P1 locks in isochoric "
                        "plastic flow (too stiff, wrong pressures) except in "
                        "homogeneous deformation. Use Polynomial degree = 2.");
          break;
        }
  }



  template double
  adaptive_cell_limit<2>(const Parameters::AllParameters &,
                         const double,
                         const MPI_Comm);
  template double
  adaptive_cell_limit<3>(const Parameters::AllParameters &,
                         const double,
                         const MPI_Comm);
  template void
  check_mesh_size<2>(const Parameters::AllParameters &,
                     const unsigned int,
                     const double);
  template void
  check_mesh_size<3>(const Parameters::AllParameters &,
                     const unsigned int,
                     const double);
  template void
  check_simplex_model<2>(const Parameters::AllParameters &,
                         const Triangulation<2> &,
                         Warnings &);
  template void
  check_simplex_model<3>(const Parameters::AllParameters &,
                         const Triangulation<3> &,
                         Warnings &);
  template void
  support_warnings<2>(const Parameters::AllParameters &,
                      const Triangulation<2> &,
                      Warnings &);
  template void
  support_warnings<3>(const Parameters::AllParameters &,
                      const Triangulation<3> &,
                      Warnings &);
} // namespace tribos
