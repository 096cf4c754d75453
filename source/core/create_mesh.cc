/**
 * The mesh of a run: the scene (or mesh file) built into a shared mesh, or
 * on the first process and partitioned into a distributed one, with a
 * second-order mesh's curved cells, checked against the parameters that
 * name its boundary ids.
 */

#include <tribos/base/cells_from_first_process.h>
#include <tribos/base/text.h>
#include <tribos/core/create_mesh.h>
#include <tribos/core/model_checks.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>

#include <set>
#include <sstream>
#include <string>

namespace tribos
{
  namespace
  {
    /**
     * The scene into the empty @p triangulation: as its generator makes it
     * (with a second-order mesh's curved geometry into @p curved), or with
     * every cell split into simplices (Finite element/Cells).
     * @p check_size gets the scene's unrefined cell count: before a
     * refined mesh is built (from the scene built at level 0), or at
     * Scene/Refinement = 0 from the mesh itself (not built twice).
     */
    template <int dim, typename SizeCheck>
    void
    create_scene(const Parameters::AllParameters &parameters,
                 Triangulation<dim>              &triangulation,
                 CurvedCells<dim>                &curved,
                 const SizeCheck                 &check_size)
    {
      const auto        &scene      = *parameters.scene.geometry;
      const unsigned int refinement = parameters.scene.refinement;
      if (refinement > 0)
      {
        Triangulation<dim> coarse;
        scene.create(0, coarse);
        check_size(coarse.n_active_cells());
      }
      if (!parameters.finite_element.split_into_simplices)
      {
        scene.create_curved(refinement, triangulation, curved);
        if (refinement == 0)
          check_size(triangulation.n_active_cells());
        return;
      }
      Triangulation<dim> cells;
      scene.create_curved(refinement, cells, curved);
      if (refinement == 0)
        check_size(cells.n_active_cells());
      AssertThrow(curved.empty(),
                  ExcMessage("Parameter <Finite element/Cells> = simplices "
                             "splits straight cells; the mesh of the scene "
                             "has second-order (curved) cells. Mesh the "
                             "body with triangles or tetrahedra in gmsh "
                             "instead."));
      AssertThrow(cells.all_reference_cells_are_hyper_cube(),
                  ExcMessage("Parameter <Finite element/Cells> = simplices "
                             "splits quadrilaterals and hexahedra; the mesh "
                             "of the scene has simplices already."));
      // deal.II splits conforming meshes only (a coarse mesh of simplices
      // has no hanging nodes).
      bool has_hanging_nodes = false;
      for (const auto &cell : cells.active_cell_iterators())
        for (const auto f : cell->face_indices())
          if (!cell->at_boundary(f) && cell->neighbor(f)->has_children())
            has_hanging_nodes = true;
      AssertThrow(!has_hanging_nodes,
                  ExcMessage("Parameter <Finite element/Cells> = simplices "
                             "splits conforming meshes only; the scene <" +
                             parameters.scene.name +
                             "> refines locally (hanging nodes): set its "
                             "local refinement to 0 (e.g. Contact "
                             "refinements) and refine with Scene/Refinement."));
      GridGenerator::convert_hypercube_to_simplex_mesh(cells, triangulation);
    }



    /** The curved geometry of the own cells of @p triangulation from the
     * first process's @p serial mesh and its @p serial_curved cells (a
     * distributed mesh of a second-order file) into @p curved_cells. */
    template <int dim>
    void
    distribute_curved_cells(const Triangulation<dim>         &serial,
                            const CurvedCells<dim>           &serial_curved,
                            parallel::TriangulationBase<dim> &triangulation,
                            CurvedCells<dim>                 &curved_cells)
    {
      const MPI_Comm mpi_communicator = triangulation.get_communicator();
      // Every process asks for the support points of its own cells (by
      // CellId, the same in the serial and the distributed mesh).
      if (Utilities::MPI::broadcast(mpi_communicator, serial_curved.empty(), 0))
        return;
      std::vector<CellId> mine;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          mine.push_back(cell->id());
      const std::vector<double> x = cells_from_first_process(
        mpi_communicator,
        serial,
        mine,
        [&](const auto &cell, std::vector<double> &numbers)
        {
          for (const auto &point :
               serial_curved.support_points[cell->active_cell_index()])
            for (unsigned int d = 0; d < dim; ++d)
              numbers.push_back(point[d]);
        });
      curved_cells.support_points.assign(triangulation.n_active_cells(), {});
      if (mine.empty())
        return;
      const unsigned int n    = x.size() / (dim * mine.size());
      unsigned int       next = 0;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          auto &points = curved_cells.support_points[cell->active_cell_index()];
          points.resize(n);
          for (auto &point : points)
            for (unsigned int d = 0; d < dim; ++d)
              point[d] = x[next++];
        }
    }


    /** Parallel/Mesh = distributed: the scene built on the first process,
     * partitioned (with @p weights per CellId after a rebalance), and this
     * process's part of it into @p triangulation. */
    template <int dim>
    void
    create_distributed_scene(const Parameters::AllParameters  &parameters,
                             parallel::TriangulationBase<dim> &triangulation,
                             CurvedCells<dim>                 &curved_cells,
                             const CellWeights                *weights)
    {
      // The scene generators build whole meshes (curved bodies refined on
      // their exact manifolds, then merged flat): the first process builds it,
      // METIS partitions it, and every process keeps its own cells and their
      // ghosts. A bad scene is reported on every process.
      const MPI_Comm     mpi_communicator = triangulation.get_communicator();
      const unsigned int n_ranks =
        Utilities::MPI::n_mpi_processes(mpi_communicator);
      // Collective, so before the first process builds the scene.
      const double       memory = run_memory(mpi_communicator);
      Triangulation<dim> serial;
      CurvedCells<dim>   serial_curved;
      std::string        error;
      if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        try
        {
          create_scene(parameters,
                       serial,
                       serial_curved,
                       [&](const unsigned int n)
                       { check_mesh_size<dim>(parameters, n, memory); });
        }
        catch (const ExceptionBase &e)
        {
          std::ostringstream text;
          e.print_info(text);
          error = text.str();
        }
        catch (const std::exception &e)
        {
          error = e.what();
        }
      }
      error = Utilities::MPI::broadcast(mpi_communicator, error, 0);
      AssertThrow(error.empty(), ExcMessage(error));

      const auto description = TriangulationDescription::Utilities::
        create_description_from_triangulation_in_groups<dim, dim>(
          [&serial](Triangulation<dim> &tria)
          {
            tria.copy_triangulation(serial);
            // The mesh is final: no refinement follows, no manifold is
            // needed on the processes.
            for (const auto &cell : tria.cell_iterators())
              cell->set_all_manifold_ids(numbers::flat_manifold_id);
            tria.reset_all_manifolds();
          },
          [&parameters, n_ranks, weights](Triangulation<dim> &tria,
                                          const MPI_Comm,
                                          const unsigned int)
          {
            // A cell that carries slave faces weighs more: its slave nodes'
            // contact elements are evaluated by its process. (No weights at
            // all is METIS' plain partition.)
            const unsigned int weight = parameters.parallel.contact_cell_weight;
            const auto slave_ids      = parameters.contact.slave_boundary_ids();
            std::vector<unsigned int> cell_weights;
            if (weight > 1)
            {
              cell_weights.assign(tria.n_active_cells(), 1);
              for (const auto &cell : tria.active_cell_iterators())
                for (const auto &face : cell->face_iterators())
                  if (face->at_boundary() &&
                      slave_ids.count(face->boundary_id()) == 1)
                    cell_weights[cell->active_cell_index()] = weight;
            }
            // After a rebalance: 1 + each cell's measured contact work, in
            // cells' assembly.
            if (weights != nullptr)
            {
              if (cell_weights.empty())
                cell_weights.assign(tria.n_active_cells(), 1);
              for (const auto &[id, w] : *weights)
              {
                auto &weight_of_cell =
                  cell_weights[tria.create_cell_iterator(CellId(id))
                                 ->active_cell_index()];
                weight_of_cell = std::max(weight_of_cell, 1 + w);
              }
            }
            GridTools::partition_triangulation(n_ranks, cell_weights, tria);
          },
          mpi_communicator,
          n_ranks);
      triangulation.create_triangulation(description);

      // Cells refined after the merge (local refinement at a contact point)
      // are refined again from the description, and their new vertices would
      // sit on straight lines: every process takes the vertices of its cells
      // from the first process's mesh, where the scene put them (on a sphere,
      // a cylinder, ...).
      const unsigned int n_levels =
        Utilities::MPI::broadcast(mpi_communicator, serial.n_levels(), 0);
      if (n_levels > 1)
      {
        std::vector<CellId> mine;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (!cell->is_artificial() && cell->level() > 0)
            mine.push_back(cell->id());
        const std::vector<double> x = cells_from_first_process(
          mpi_communicator,
          serial,
          mine,
          [](const auto &cell, std::vector<double> &numbers)
          {
            for (const unsigned int v : cell->vertex_indices())
              for (unsigned int d = 0; d < dim; ++d)
                numbers.push_back(cell->vertex(v)[d]);
          });
        unsigned int next = 0;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (!cell->is_artificial() && cell->level() > 0)
            for (const unsigned int v : cell->vertex_indices())
              for (unsigned int d = 0; d < dim; ++d)
                cell->vertex(v)[d] = x[next++];
      }
      distribute_curved_cells(serial,
                              serial_curved,
                              triangulation,
                              curved_cells);
    }


    /**
     * Adaptivity/Enable: the scene built on every process (a coarse scene
     * is small and its generator deterministic) and its cells made the
     * coarse cells of the p4est mesh @p triangulation, with the scene's
     * manifolds (new vertices of a refined curved surface lie on it).
     */
    template <int dim>
    void
    create_adaptive_scene(const Parameters::AllParameters  &parameters,
                          parallel::TriangulationBase<dim> &triangulation)
    {
      const MPI_Comm     mpi_communicator = triangulation.get_communicator();
      const double       memory           = run_memory(mpi_communicator);
      Triangulation<dim> serial;
      CurvedCells<dim>   curved;
      create_scene(parameters,
                   serial,
                   curved,
                   [&](const unsigned int n)
                   { check_mesh_size<dim>(parameters, n, memory); });
      const std::string refused =
        "Parameter <Adaptivity/Enable> = true: the scene's cells become the "
        "coarse cells of a p4est mesh, ";
      AssertThrow(serial.all_reference_cells_are_hyper_cube(),
                  ExcMessage(refused +
                             "which must be quadrilaterals or hexahedra "
                             "(deal.II 9.4 has no hanging nodes on "
                             "triangles and tetrahedra); the mesh of the "
                             "scene has simplices."));
      AssertThrow(curved.empty(),
                  ExcMessage(refused +
                             "whose geometry is their vertices and the "
                             "scene's manifolds; a second-order mesh file's "
                             "curved cells are not carried over a "
                             "refinement yet. Use a first-order mesh."));
      AssertThrow(!serial.has_hanging_nodes(),
                  ExcMessage(refused + "which must be conforming; the scene <" +
                             parameters.scene.name +
                             "> refines locally (hanging nodes): set its "
                             "local refinement to 0 (e.g. Contact "
                             "refinements, Box refinements) and let the "
                             "adaptation refine."));
      GridGenerator::flatten_triangulation(serial, triangulation);
      for (const auto id : serial.get_manifold_ids())
        if (id != numbers::flat_manifold_id)
          triangulation.set_manifold(id, serial.get_manifold(id));

      // A cell with a slave face weighs more in p4est's partition (as in
      // METIS', Parallel/Contact cell weight).
      const unsigned int weight = parameters.parallel.contact_cell_weight;
      if (weight > 1)
      {
        const auto slave_ids = parameters.contact.slave_boundary_ids();
        triangulation.signals.weight.connect(
          [weight, slave_ids](
            const typename Triangulation<dim>::cell_iterator &cell,
            const typename Triangulation<dim>::CellStatus) -> unsigned int
          {
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary() &&
                  slave_ids.count(face->boundary_id()) == 1)
                return weight;
            return 1;
          });
      }
    }
  } // namespace



  template <int dim>
  std::unique_ptr<parallel::TriangulationBase<dim>>
  make_triangulation(const Parameters::AllParameters &parameters,
                     const MPI_Comm                   mpi_communicator)
  {
    if (parameters.adaptivity.enable)
      return std::make_unique<parallel::distributed::Triangulation<dim>>(
        mpi_communicator,
        Triangulation<dim>::limit_level_difference_at_vertices);
    if (parameters.parallel.mesh == Parameters::Parallel::Mesh::shared)
      return std::make_unique<parallel::shared::Triangulation<dim>>(
        mpi_communicator);
    return std::make_unique<parallel::fullydistributed::Triangulation<dim>>(
      mpi_communicator);
  }



  template <int dim>
  void
  create_mesh(const Parameters::AllParameters  &parameters,
              parallel::TriangulationBase<dim> &triangulation,
              CurvedCells<dim>                 &curved_cells,
              const CellWeights                *weights,
              Warnings                         &warnings)
  {
    const MPI_Comm mpi_communicator = triangulation.get_communicator();
    curved_cells                    = {};
    if (parameters.adaptivity.enable)
      create_adaptive_scene(parameters, triangulation);
    else if (parameters.parallel.mesh == Parameters::Parallel::Mesh::shared)
    {
      const double memory = run_memory(mpi_communicator);
      create_scene(parameters,
                   triangulation,
                   curved_cells,
                   [&](const unsigned int n)
                   { check_mesh_size<dim>(parameters, n, memory); });
    }
    else
      create_distributed_scene(parameters,
                               triangulation,
                               curved_cells,
                               weights);
    if (!triangulation.all_reference_cells_are_hyper_cube())
      check_simplex_model<dim>(parameters, triangulation, warnings);

    // Every boundary id named in a condition must exist in the mesh (the
    // faces of own cells: on a distributed mesh the outer faces of the
    // ghost layer are boundary faces with id 0 too).
    std::set<types::boundary_id> existing;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            existing.insert(face->boundary_id());
    existing = Utilities::MPI::compute_set_union(existing, mpi_communicator);
    const auto require = [&](const unsigned int id, const std::string &entry)
    {
      AssertThrow(existing.count(id) == 1,
                  ExcMessage("Parameter <Boundary conditions/" + entry +
                             "> names boundary id " + std::to_string(id) +
                             ", which scene <" + parameters.scene.name +
                             "> does not have. Its boundary ids are " +
                             Text::join(existing) +
                             (parameters.scene.name == "gmsh" ?
                                " (a gmsh mesh's boundary ids are the "
                                "physical group tags of its boundary lines "
                                "in 2D, surfaces in 3D)." :
                                "; the README lists what each one is.")));
    };
    for (const auto &c : parameters.boundary_conditions.dirichlet)
      require(c.boundary_id, "Dirichlet");
    for (const auto id : parameters.boundary_conditions.symmetry)
      require(id, "Symmetry");
    for (const auto &c : parameters.boundary_conditions.neumann)
      require(c.boundary_id, "Neumann");
  }



  template std::unique_ptr<parallel::TriangulationBase<2>>
  make_triangulation<2>(const Parameters::AllParameters &, const MPI_Comm);
  template std::unique_ptr<parallel::TriangulationBase<3>>
  make_triangulation<3>(const Parameters::AllParameters &, const MPI_Comm);
  template void
  create_mesh<2>(const Parameters::AllParameters &,
                 parallel::TriangulationBase<2> &,
                 CurvedCells<2> &,
                 const CellWeights *,
                 Warnings &);
  template void
  create_mesh<3>(const Parameters::AllParameters &,
                 parallel::TriangulationBase<3> &,
                 CurvedCells<3> &,
                 const CellWeights *,
                 Warnings &);
} // namespace tribos
