/**
 * The linear system of the problem: its constraints (hanging nodes,
 * Dirichlet, symmetry), its sparsity pattern (the bulk and the contact
 * couplings), and the rigid-body modes AMG needs.
 */

#include <tribos/base/import_constraints.h>
#include <tribos/core/problem.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <map>
#include <set>

namespace tribos
{
  template <int dim>
  void
  Problem<dim>::make_sparsity()
  {
    // Contact couples slave nodes with master faces of other cells, often of
    // other bodies: those couplings join the bulk pattern, and the pattern
    // is rebuilt when the search meets a new slave-face pair.
    DynamicSparsityPattern dsp(system_coupled);
    if (n_multipliers == 0)
      DoFTools::make_sparsity_pattern(dof_handler,
                                      dsp,
                                      homogeneous_constraints,
                                      false);
    else
    {
      // The bulk pattern on the dofs alone, copied into the system's.
      DynamicSparsityPattern bulk(locally_relevant_dofs);
      DoFTools::make_sparsity_pattern(dof_handler,
                                      bulk,
                                      homogeneous_constraints,
                                      false);
      for (const auto row : locally_relevant_dofs)
        for (auto entry = bulk.begin(row); entry != bulk.end(row); ++entry)
          dsp.add(row, entry->column());
    }
    if (contact_handler)
      contact_handler->add_couplings(dsp, homogeneous_constraints);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               system_owned,
                                               mpi_communicator,
                                               system_coupled);
    // Whatever holds on to the old matrix goes first.
    if (linear_solver != nullptr)
      linear_solver->release_matrix();
    matrix.reinit(system_owned, system_owned, dsp, mpi_communicator);
    ++sparsity_version;
  }



  template <int dim>
  void
  Problem<dim>::fix_symmetry_corners(const std::set<types::boundary_id> &ids,
                                     AffineConstraints<double> &symmetry) const
  {
    // The unit normals of the symmetry faces at each vertex (named by its
    // first dof, with all its dofs), from the faces' first three corners
    // (flat faces).
    std::map<types::global_dof_index,
             std::pair<std::vector<types::global_dof_index>,
                       std::vector<Tensor<1, dim>>>>
      vertices;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              ids.count(cell->face(f)->boundary_id()) == 1)
          {
            const auto     face = cell->face(f);
            Tensor<1, dim> normal;
            if constexpr (dim == 3)
              normal = cross_product_3d(face->vertex(1) - face->vertex(0),
                                        face->vertex(2) - face->vertex(0));
            if (normal.norm() == 0)
              continue;
            normal /= normal.norm();
            for (const auto v : face->vertex_indices())
            {
              auto &vertex = vertices[face->vertex_dof_index(v, 0)];
              if (vertex.first.empty())
                for (unsigned int d = 0; d < dim; ++d)
                  vertex.first.push_back(face->vertex_dof_index(v, d));
              vertex.second.push_back(normal);
            }
          }
    // A vertex where three independent symmetry planes meet is fixed: its
    // faces' normals fall into at least three directions (apart by more
    // than 18 degrees, so that the facets of a curved surface do not count)
    // that span space.
    std::set<types::global_dof_index> corner_dofs;
    for (const auto &[first, vertex] : vertices)
    {
      std::vector<Tensor<1, dim>> directions;
      for (const auto &n : vertex.second)
        if (std::none_of(directions.begin(),
                         directions.end(),
                         [&n](const Tensor<1, dim> &d)
                         { return std::abs(d * n) > 0.95; }))
          directions.push_back(n);
      bool corner = false;
      for (unsigned int a = 0; a < directions.size() && !corner; ++a)
        for (unsigned int b = a + 1; b < directions.size() && !corner; ++b)
          for (unsigned int c = b + 1; c < directions.size() && !corner; ++c)
          {
            Tensor<2, dim> m;
            for (unsigned int d = 0; d < dim; ++d)
            {
              m[0][d]       = directions[a][d];
              m[1][d]       = directions[b][d];
              m[2 % dim][d] = directions[c][d];
            }
            corner = std::abs(determinant(m)) > 0.05;
          }
      if (corner)
        corner_dofs.insert(vertex.first.begin(), vertex.first.end());
    }
    if (Utilities::MPI::max(corner_dofs.empty() ? 0 : 1, mpi_communicator) == 0)
      return;
    AffineConstraints<double> fixed(symmetry.get_local_lines());
    for (const auto &line : symmetry.get_lines())
      if (corner_dofs.count(line.index) == 0)
      {
        fixed.add_line(line.index);
        fixed.add_entries(line.index, line.entries);
        fixed.set_inhomogeneity(line.index, line.inhomogeneity);
      }
    for (const auto dof : corner_dofs)
      fixed.add_line(dof);
    fixed.close();
    symmetry.copy_from(fixed);
  }



  template <int dim>
  void
  Problem<dim>::make_constraints(const double               time,
                                 const bool                 homogeneous,
                                 AffineConstraints<double> &constraints) const
  {
    constraints.clear();
    constraints.reinit(system_coupled);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);

    // Dirichlet: du = g(t) - u on the constrained dofs, or du = 0.
    const auto &bc = parameters.boundary_conditions;
    for (unsigned int i = 0; i < bc.dirichlet.size(); ++i)
    {
      const auto &c        = bc.dirichlet[i];
      auto       &function = *dirichlet_functions[i];
      function.set_time(time);
      for (unsigned int k = 0; k < c.components.size(); ++k)
      {
        const unsigned int d = c.components[k];
        ComponentMask      mask(dim, false);
        mask.set(d, true);
        std::map<types::global_dof_index, double> values;
        // Expand the k-th expression to a dim-vector function whose
        // component d is that expression.
        const auto scalar = [&function, k](const Point<dim> &p)
        {
          return function.value(p, k);
        };
        VectorFunctionFromScalarFunctionObject<dim> component(scalar, d, dim);
        VectorTools::interpolate_boundary_values(dof_handler,
                                                 c.boundary_id,
                                                 component,
                                                 values,
                                                 mask);
        for (const auto &[dof, value] : values)
          if (locally_relevant_dofs.is_element(dof) &&
              !constraints.is_constrained(dof))
          {
            constraints.add_line(dof);
            if (!homogeneous)
              constraints.set_inhomogeneity(dof, value - ghosted_solution[dof]);
          }
      }
    }

    if (!bc.symmetry.empty())
    {
      AffineConstraints<double>          symmetry(system_coupled);
      const std::set<types::boundary_id> ids(bc.symmetry.begin(),
                                             bc.symmetry.end());
      VectorTools::compute_no_normal_flux_constraints(
        dof_handler,
        0,
        ids,
        symmetry,
        fe->reference_cell().template get_default_linear_mapping<dim>());
      symmetry.close();
      if (dim == 3 && !triangulation.all_reference_cells_are_hyper_cube())
        fix_symmetry_corners(ids, symmetry);
      // Merging substitutes the symmetry lines into the hanging-node lines
      // that refer to them. On a distributed mesh the outer faces of the
      // ghost layer are boundary faces with id 0 of the local mesh, so a
      // dof there that this process does not own may have a symmetry line
      // it should not have; substituted, it would take a parent's weight
      // out of the line of a hanging node this process owns. Only the own
      // lines are merged: the others come from their owners below, and
      // close() resolves the chains.
      if (parameters.parallel.mesh == Parameters::Parallel::Mesh::distributed)
      {
        AffineConstraints<double> own(system_coupled);
        for (const auto &line : symmetry.get_lines())
          if (locally_owned_dofs.is_element(line.index))
          {
            own.add_line(line.index);
            own.add_entries(line.index, line.entries);
            own.set_inhomogeneity(line.index, line.inhomogeneity);
          }
        symmetry.copy_from(own);
      }
      constraints.merge(
        symmetry,
        AffineConstraints<double>::MergeConflictBehavior::left_object_wins);
    }
    // On a distributed mesh, every dof this process does not own (ghosts,
    // and the master and slave dofs of other processes' cells) as its owner
    // constrains it. A shared mesh has every cell on every process.
    if (parameters.parallel.mesh == Parameters::Parallel::Mesh::distributed)
      import_constraints(constraints,
                         owned_per_process,
                         coupled_dofs,
                         mpi_communicator);
    constraints.close();
  }



  template <int dim>
  std::vector<std::vector<double>>
  Problem<dim>::rigid_body_modes() const
  {
    // The support points of the dofs (reference configuration).
    std::map<types::global_dof_index, Point<dim>> points;
    DoFTools::map_dofs_to_support_points(
      fe->reference_cell().template get_default_linear_mapping<dim>(),
      dof_handler,
      points);
    // About the centroid of all support points (every process the same).
    Tensor<1, dim> sum;
    for (const auto dof : locally_owned_dofs)
      sum += points.at(dof);
    const Point<dim>   centre(Utilities::MPI::sum(sum, mpi_communicator) /
                              double(dof_handler.n_dofs()));
    const unsigned int n_modes = dim == 2 ? 3 : 6;
    std::vector<std::vector<double>> modes(
      n_modes,
      std::vector<double>(system_owned.n_elements(), 0.));
    unsigned int local = 0;
    for (const auto dof : system_owned)
    {
      if (dof < dof_handler.n_dofs())
      {
        const unsigned int   c = dof_component[dof];
        const Tensor<1, dim> x = points.at(dof) - centre;
        modes[c][local]        = 1; // translations
        // Rotations: about z in 2D (-y, x); about x, y, z in 3D.
        if constexpr (dim == 2)
          modes[2][local] = (c == 0 ? -x[1] : x[0]);
        else
        {
          const double rotation[3][3] = {{0, -x[2], x[1]},
                                         {x[2], 0, -x[0]},
                                         {-x[1], x[0], 0}};
          for (unsigned int r = 0; r < 3; ++r)
            modes[3 + r][local] = rotation[r][c];
        }
      }
      ++local;
    }
    return modes;
  }

  template class Problem<2>;
  template class Problem<3>;
} // namespace tribos
