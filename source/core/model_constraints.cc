/**
 * The Model's constraints (hanging nodes, Dirichlet, symmetry), the cells'
 * sparsity pattern, and the rigid-body modes AMG needs.
 */

#include <tribos/base/import_constraints.h>
#include <tribos/core/model.h>
#include <tribos/core/symmetry_constraints.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <map>
#include <set>

namespace tribos
{
  template <int dim>
  void
  Model<dim>::make_constraints(const double               time,
                               const Vector              *ghosted_solution,
                               AffineConstraints<double> &constraints) const
  {
    constraints.clear();
    constraints.reinit(layout_.system_coupled);
    DoFTools::make_hanging_node_constraints(dofs, constraints);

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
        VectorTools::interpolate_boundary_values(mapping(),
                                                 dofs,
                                                 c.boundary_id,
                                                 component,
                                                 values,
                                                 mask);
        for (const auto &[dof, value] : values)
          if (layout_.locally_relevant_dofs.is_element(dof) &&
              !constraints.is_constrained(dof))
          {
            constraints.add_line(dof);
            if (ghosted_solution != nullptr)
              constraints.set_inhomogeneity(dof,
                                            value - (*ghosted_solution)[dof]);
          }
      }
    }

    if (!bc.symmetry.empty())
    {
      AffineConstraints<double>          symmetry(layout_.system_coupled);
      const std::set<types::boundary_id> ids(bc.symmetry.begin(),
                                             bc.symmetry.end());
      // tribos's own constraints, which group the faces' normals by
      // direction, not by cell (make_symmetry_constraints()): deal.II 9.4's
      // compute_no_normal_flux_constraints() leaves the nodes on the edge
      // where two symmetry planes meet free to slide when the cells there
      // are gmsh tetrahedra or curved hexahedra.
      make_symmetry_constraints(mapping(), dofs, ids, symmetry);
      symmetry.close();
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
        AffineConstraints<double> own(layout_.system_coupled);
        for (const auto &line : symmetry.get_lines())
          if (layout_.locally_owned_dofs.is_element(line.index))
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
                         layout_.coupled_dofs,
                         mpi_communicator);
    constraints.close();
  }



  template <int dim>
  void
  Model<dim>::bulk_sparsity(DynamicSparsityPattern &dsp) const
  {
    if (layout_.n_multipliers == 0)
      DoFTools::make_sparsity_pattern(dofs, dsp, homogeneous, false);
    else
    {
      // The bulk pattern on the dofs alone, copied into the system's.
      DynamicSparsityPattern bulk(layout_.locally_relevant_dofs);
      DoFTools::make_sparsity_pattern(dofs, bulk, homogeneous, false);
      for (const auto row : layout_.locally_relevant_dofs)
        for (auto entry = bulk.begin(row); entry != bulk.end(row); ++entry)
          dsp.add(row, entry->column());
    }
  }



  template <int dim>
  std::vector<std::vector<double>>
  Model<dim>::rigid_body_modes() const
  {
    // The support points of the dofs (reference configuration).
    std::map<types::global_dof_index, Point<dim>> points;
    DoFTools::map_dofs_to_support_points(mapping(), dofs, points);
    // About the centroid of all support points (every process the same).
    Tensor<1, dim> sum;
    for (const auto dof : layout_.locally_owned_dofs)
      sum += points.at(dof);
    const Point<dim>   centre(Utilities::MPI::sum(sum, mpi_communicator) /
                              double(dofs.n_dofs()));
    const unsigned int n_modes = dim == 2 ? 3 : 6;
    std::vector<std::vector<double>> modes(
      n_modes,
      std::vector<double>(layout_.system_owned.n_elements(), 0.));
    unsigned int local = 0;
    for (const auto dof : layout_.system_owned)
    {
      if (dof < dofs.n_dofs())
      {
        const unsigned int   c = components[dof];
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



  template class Model<2>;
  template class Model<3>;
} // namespace tribos
