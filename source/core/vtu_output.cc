#include <tribos/base/write_atomically.h>
#include <tribos/core/problem.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/data_out.h>

#include <cmath>

namespace tribos
{
  template <int dim>
  void
  Problem<dim>::write_vtu(const unsigned int step, const double time)
  {
    TimerOutput::Scope t(timer, "output");
    const std::string  dir = parameters.output.directory + "/";
    if (contact)
      contact_output->write_csv(dir + "contact-" +
                                Utilities::int_to_string(step, 5) + ".csv");
    if (!parameters.output.write_vtu)
      return;

    // Cell averages of the Cauchy stress: honest for every material,
    // including those whose stress lives only at quadrature points.
    const unsigned int n_stress = (dim == 2 ? 4 : 6);
    const unsigned int stress_index[6][2] =
      {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};
    const char                         *stress_names[6] = {"stress_xx",
                                                           "stress_yy",
                                                           "stress_zz",
                                                           "stress_xy",
                                                           "stress_yz",
                                                           "stress_xz"};
    std::vector<dealii::Vector<double>> stress(
      n_stress,
      dealii::Vector<double>(triangulation.n_active_cells()));
    dealii::Vector<double> von_mises(triangulation.n_active_cells());
    dealii::Vector<double> plastic_strain(triangulation.n_active_cells());
    dealii::Vector<double> body_id(triangulation.n_active_cells());
    dealii::Vector<double> subdomain(triangulation.n_active_cells());
    bool                   any_history = false;
    for (const auto &m : materials)
      any_history = any_history || m->n_history_variables() > 0;
    for (const auto &m : axisymmetric_materials)
      any_history = any_history || m->n_history_variables() > 0;

    const bool axisymmetric = parameters.finite_element.axisymmetric;
    std::vector<SymmetricTensor<2, 3>> sums(triangulation.n_active_cells());
    std::vector<double>                volume(triangulation.n_active_cells()),
      peeq(triangulation.n_active_cells());
    for_each_material_point(
      [&](const auto           &cell,
          const FEValues<dim>  &fe_values,
          const unsigned int    q,
          const Tensor<2, dim> &F,
          const Tensor<2, 3>   &F3,
          const double         *history)
      {
        // Axisymmetric: stress_zz is the hoop stress.
        const unsigned int index = cell->active_cell_index();
        const double       JxW   = fe_values.JxW(q);
        if (axisymmetric)
        {
          const auto &material = *axisymmetric_materials[cell->material_id()];
          sums[index] += JxW * material.cauchy_stress(F3, history);
          peeq[index] += JxW * material.equivalent_plastic_strain(history);
        }
        else
        {
          const auto &material = *materials[cell->material_id()];
          sums[index] += JxW * material.cauchy_stress(F, history);
          peeq[index] += JxW * material.equivalent_plastic_strain(history);
        }
        volume[index] += JxW;
      });
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        const unsigned int          index   = cell->active_cell_index();
        const SymmetricTensor<2, 3> average = sums[index] / volume[index];
        for (unsigned int s = 0; s < n_stress; ++s)
          stress[s][index] = average[stress_index[s][0]][stress_index[s][1]];
        const SymmetricTensor<2, 3> dev = deviator(average);
        von_mises[index]                = std::sqrt(1.5 * (dev * dev));
        plastic_strain[index]           = peeq[index] / volume[index];
        body_id[index]                  = cell->material_id();
        subdomain[index]                = cell->subdomain_id();
      }

    DataOut<dim> data_out;
    data_out.attach_dof_handler(dof_handler);
    using cell_iterator = typename Triangulation<dim>::active_cell_iterator;
    const auto next_owned =
      [](const Triangulation<dim> &tria, cell_iterator cell)
    {
      while (cell != tria.end() && !cell->is_locally_owned())
        ++cell;
      return cell;
    };
    data_out.set_cell_selection(
      [next_owned](const Triangulation<dim> &tria)
      { return next_owned(tria, tria.begin_active()); },
      [next_owned](const Triangulation<dim>                         &tria,
                   const typename Triangulation<dim>::cell_iterator &cell)
      {
        cell_iterator next(cell);
        return next_owned(tria, ++next);
      });
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(dim,
                     DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(ghosted_displacement(),
                             std::vector<std::string>(dim, "displacement"),
                             DataOut<dim>::type_dof_data,
                             interpretation);
    if (integrator)
      data_out.add_data_vector(ghosted_velocity,
                               std::vector<std::string>(dim, "velocity"),
                               DataOut<dim>::type_dof_data,
                               interpretation);
    for (unsigned int s = 0; s < n_stress; ++s)
      data_out.add_data_vector(stress[s], stress_names[s]);
    data_out.add_data_vector(von_mises, "von_mises");
    if (any_history)
      data_out.add_data_vector(plastic_strain, "PEEQ");
    data_out.add_data_vector(body_id, "body_id");
    // Contact fields at the slave nodes, under the names Abaqus and
    // CalculiX users know: scalars on the support points of the mesh's
    // degree (on Q2 the faces' middle nodes carry contact too), CSHEAR as a
    // vector.
    FE_Q<dim>       node_fe(parameters.finite_element.degree);
    DoFHandler<dim> node_dof_handler(triangulation);
    std::array<TrilinosWrappers::MPI::Vector, 4> contact_scalars;
    Vector                                       contact_shear;
    Vector                                       contact_force;
    if (contact)
    {
      // The contact force on every node (slave and master), the nodal
      // resultant of the contact tractions.
      Vector owned(locally_owned_dofs, mpi_communicator);
      for (const auto i : locally_owned_dofs)
        owned[i] = contact_forces[i];
      owned.compress(VectorOperation::insert);
      contact_force.reinit(locally_owned_dofs,
                           locally_relevant_dofs,
                           mpi_communicator);
      contact_force = owned;
      data_out.add_data_vector(contact_force,
                               std::vector<std::string>(dim, "contact_force"),
                               DataOut<dim>::type_dof_data,
                               interpretation);
      node_dof_handler.distribute_dofs(node_fe);
      std::map<types::global_dof_index, types::global_dof_index> scalar_dof;
      std::vector<types::global_dof_index> cell_dofs(fe->n_dofs_per_cell()),
        node_dofs(node_fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
        {
          const typename DoFHandler<dim>::active_cell_iterator node_cell(
            &triangulation,
            cell->level(),
            cell->index(),
            &node_dof_handler);
          cell->get_dof_indices(cell_dofs);
          node_cell->get_dof_indices(node_dofs);
          // The x dof of each support point names the node.
          for (unsigned int i = 0; i < cell_dofs.size(); ++i)
          {
            const auto [component, index] = fe->system_to_component_index(i);
            if (component == 0)
              scalar_dof[cell_dofs[i]] = node_dofs[index];
          }
        }
      const IndexSet node_owned = node_dof_handler.locally_owned_dofs();
      IndexSet       node_relevant;
      DoFTools::extract_locally_relevant_dofs(node_dof_handler, node_relevant);
      for (auto &v : contact_scalars)
        v.reinit(node_owned, mpi_communicator);
      Vector owned_shear(locally_owned_dofs, mpi_communicator);
      contact_output->nodal_fields(scalar_dof, contact_scalars, owned_shear);
      contact_shear.reinit(locally_owned_dofs,
                           locally_relevant_dofs,
                           mpi_communicator);
      contact_shear = owned_shear;
      for (auto &v : contact_scalars)
      {
        Vector ghosted(node_owned, node_relevant, mpi_communicator);
        ghosted = v;
        v.swap(ghosted);
      }
      const char *names[4] = {"CPRESS", "COPEN", "CSLIP", "CSTATUS"};
      for (unsigned int i = 0; i < 4; ++i)
        data_out.add_data_vector(node_dof_handler,
                                 contact_scalars[i],
                                 names[i]);
      data_out.add_data_vector(contact_shear,
                               std::vector<std::string>(dim, "CSHEAR"),
                               DataOut<dim>::type_dof_data,
                               interpretation);
    }

    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(mpi_communicator);
    const unsigned int rank =
      Utilities::MPI::this_mpi_process(mpi_communicator);
    if (n_ranks > 1)
      data_out.add_data_vector(subdomain, "subdomain");
    data_out.build_patches(parameters.finite_element.degree);

    // zlib's fastest level: deal.II's default (best compression) took five
    // times as long for files 12 % smaller (Hertz 2D, doc/benchmarks.md).
    DataOutBase::VtkFlags flags;
    flags.time              = time;
    flags.cycle             = step;
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);

    const std::string base = "solution-" + Utilities::int_to_string(step, 5);
    if (n_ranks == 1)
    {
      write_atomically(dir + base + ".vtu",
                       [&](std::ostream &out) { data_out.write_vtu(out); });
      pvd_records.emplace_back(time, base + ".vtu");
    }
    else
    {
      const std::string piece =
        base + "." + Utilities::int_to_string(rank, 4) + ".vtu";
      write_atomically(dir + piece,
                       [&](std::ostream &out) { data_out.write_vtu(out); });
      MPI_Barrier(mpi_communicator);
      if (rank == 0)
      {
        std::vector<std::string> pieces;
        for (unsigned int r = 0; r < n_ranks; ++r)
          pieces.push_back(base + "." + Utilities::int_to_string(r, 4) +
                           ".vtu");
        write_atomically(dir + base + ".pvtu",
                         [&](std::ostream &out)
                         { data_out.write_pvtu_record(out, pieces); });
      }
      pvd_records.emplace_back(time, base + ".pvtu");
    }
    if (rank == 0)
      write_atomically(dir + "solution.pvd",
                       [&](std::ostream &out)
                       { DataOutBase::write_pvd_record(out, pvd_records); });
  }



  template class Problem<2>;
  template class Problem<3>;
} // namespace tribos
