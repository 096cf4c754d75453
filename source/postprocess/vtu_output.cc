#include <tribos/base/write_atomically.h>
#include <tribos/postprocess/run_output.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/data_out.h>

#include <cmath>

namespace tribos
{
  namespace
  {
    using Vector = TrilinosWrappers::MPI::Vector;

    /** The cell fields of the VTU (per active cell of this process). */
    struct CellFields
    {
      std::vector<dealii::Vector<double>> stress;
      dealii::Vector<double> von_mises, plastic_strain, body_id, subdomain;
    };

    /** The names of the stress components written, and their indices. */
    const char *const  stress_names[6] = {"stress_xx",
                                          "stress_yy",
                                          "stress_zz",
                                          "stress_xy",
                                          "stress_yz",
                                          "stress_xz"};
    const unsigned int stress_index[6][2] =
      {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};

    /**
     * Cell averages of the Cauchy stress (axisymmetric: stress_zz is the
     * hoop stress), von Mises, PEEQ, the body and the process of every own
     * cell of @p problem: honest for every material, including those whose
     * stress lives only at quadrature points.
     */
    template <int dim>
    void
    compute_cell_fields(const Model<dim>   &model,
                        const Problem<dim> &problem,
                        CellFields         &fields)
    {
      const auto        &triangulation = model.triangulation();
      const auto        &materials     = problem.materials();
      const unsigned int n_cells       = triangulation.n_active_cells();
      const unsigned int n_stress      = (dim == 2 ? 4 : 6);
      fields.stress.assign(n_stress, dealii::Vector<double>(n_cells));
      for (auto *v : {&fields.von_mises,
                      &fields.plastic_strain,
                      &fields.body_id,
                      &fields.subdomain})
        v->reinit(n_cells);
      std::vector<SymmetricTensor<2, 3>> sums(n_cells);
      std::vector<double>                volume(n_cells), peeq(n_cells);
      problem.bulk().for_each_material_point(
        problem.displacement(),
        [&](const auto               &cell,
            const Kinematics<dim>    &kinematics,
            const unsigned int        q,
            const MaterialPoint<dim> &point)
        {
          const unsigned int index   = cell->active_cell_index();
          const double       JxW     = kinematics.values().JxW(q);
          const auto         body    = cell->material_id();
          const double      *history = materials.old_history(cell, q);
          sums[index] += JxW * materials.cauchy_stress(body, point, history);
          peeq[index] +=
            JxW * materials.equivalent_plastic_strain(body, history);
          volume[index] += JxW;
        });
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          const unsigned int          index   = cell->active_cell_index();
          const SymmetricTensor<2, 3> average = sums[index] / volume[index];
          for (unsigned int s = 0; s < n_stress; ++s)
            fields.stress[s][index] =
              average[stress_index[s][0]][stress_index[s][1]];
          const SymmetricTensor<2, 3> dev = deviator(average);
          fields.von_mises[index]         = std::sqrt(1.5 * (dev * dev));
          fields.plastic_strain[index]    = peeq[index] / volume[index];
          fields.body_id[index]           = cell->material_id();
          fields.subdomain[index]         = cell->subdomain_id();
        }
    }



    /** The contact fields of the VTU and the numbering they live on. */
    template <int dim>
    struct ContactFields
    {
      ContactFields(const Triangulation<dim> &triangulation,
                    const FiniteElement<dim> &displacement_fe)
        : node_fe(displacement_fe.base_element(0).clone())
        , node_dof_handler(triangulation)
      {
      }

      /** The scalar element of the displacement (FE_Q or FE_SimplexP). */
      std::unique_ptr<FiniteElement<dim>> node_fe;
      DoFHandler<dim>                     node_dof_handler;
      std::array<Vector, 4>               scalars;
      Vector                              shear, force;
    };



    /**
     * The contact fields at the slave nodes, under the names Abaqus and
     * CalculiX users know: scalars on the support points of the mesh's
     * degree (on Q2 the faces' middle nodes carry contact too), CSHEAR as
     * a vector; and the contact force on every node (slave and master),
     * the nodal resultant of the contact tractions. Added to @p data_out.
     */
    template <int dim>
    void
    add_contact_fields(const Model<dim>         &model,
                       const Problem<dim>       &problem,
                       const ContactOutput<dim> &contact_output,
                       ContactFields<dim>       &fields,
                       DataOut<dim>             &data_out)
    {
      const MPI_Comm  communicator = model.communicator();
      const auto     &owned_dofs   = model.layout().locally_owned_dofs;
      const auto     &fe           = model.fe();
      const auto     &dof_handler  = model.dof_handler();
      const IndexSet &relevant     = model.layout().locally_relevant_dofs;
      const std::vector<
        DataComponentInterpretation::DataComponentInterpretation>
        interpretation(
          dim,
          DataComponentInterpretation::component_is_part_of_vector);
      Vector owned(owned_dofs, communicator);
      for (const auto i : owned_dofs)
        owned[i] = problem.contact_forces()[i];
      owned.compress(VectorOperation::insert);
      fields.force.reinit(owned_dofs, relevant, communicator);
      fields.force = owned;
      data_out.add_data_vector(fields.force,
                               std::vector<std::string>(dim, "contact_force"),
                               DataOut<dim>::type_dof_data,
                               interpretation);
      auto &node_dof_handler = fields.node_dof_handler;
      node_dof_handler.distribute_dofs(*fields.node_fe);
      std::map<types::global_dof_index, types::global_dof_index> scalar_dof;
      std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell()),
        node_dofs(fields.node_fe->n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
        {
          const typename DoFHandler<dim>::active_cell_iterator node_cell(
            &model.triangulation(),
            cell->level(),
            cell->index(),
            &node_dof_handler);
          cell->get_dof_indices(cell_dofs);
          node_cell->get_dof_indices(node_dofs);
          // The x dof of each support point names the node.
          for (unsigned int i = 0; i < cell_dofs.size(); ++i)
          {
            const auto [component, index] = fe.system_to_component_index(i);
            if (component == 0)
              scalar_dof[cell_dofs[i]] = node_dofs[index];
          }
        }
      const IndexSet node_owned = node_dof_handler.locally_owned_dofs();
      IndexSet       node_relevant;
      DoFTools::extract_locally_relevant_dofs(node_dof_handler, node_relevant);
      for (auto &v : fields.scalars)
        v.reinit(node_owned, communicator);
      Vector owned_shear(owned_dofs, communicator);
      contact_output.nodal_fields(scalar_dof, fields.scalars, owned_shear);
      fields.shear.reinit(owned_dofs, relevant, communicator);
      fields.shear = owned_shear;
      for (auto &v : fields.scalars)
      {
        Vector ghosted(node_owned, node_relevant, communicator);
        ghosted = v;
        v.swap(ghosted);
      }
      const char *names[4] = {"CPRESS", "COPEN", "CSLIP", "CSTATUS"};
      for (unsigned int i = 0; i < 4; ++i)
        data_out.add_data_vector(node_dof_handler, fields.scalars[i], names[i]);
      data_out.add_data_vector(fields.shear,
                               std::vector<std::string>(dim, "CSHEAR"),
                               DataOut<dim>::type_dof_data,
                               interpretation);
    }
  } // namespace



  template <int dim>
  void
  RunOutput<dim>::write_step(const unsigned int step, const double time)
  {
    TimerOutput::Scope t(timer, "output");
    const std::string  dir = parameters.output.directory + "/";
    if (contact_output)
      contact_output->write_csv(dir + "contact-" +
                                Utilities::int_to_string(step, 5) + ".csv");
    if (!parameters.output.write_vtu)
      return;

    CellFields cells;
    compute_cell_fields(model, problem, cells);
    DataOut<dim> data_out;
    data_out.attach_dof_handler(model.dof_handler());
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
    data_out.add_data_vector(problem.displacement(),
                             std::vector<std::string>(dim, "displacement"),
                             DataOut<dim>::type_dof_data,
                             interpretation);
    if (problem.dynamics() != nullptr)
      data_out.add_data_vector(problem.dynamics()->velocity(),
                               std::vector<std::string>(dim, "velocity"),
                               DataOut<dim>::type_dof_data,
                               interpretation);
    for (unsigned int s = 0; s < cells.stress.size(); ++s)
      data_out.add_data_vector(cells.stress[s], stress_names[s]);
    data_out.add_data_vector(cells.von_mises, "von_mises");
    if (problem.materials().any_history())
      data_out.add_data_vector(cells.plastic_strain, "PEEQ");
    data_out.add_data_vector(cells.body_id, "body_id");
    // Adaptivity: the indicator that decided the mesh change after this
    // output (when one was computed on this mesh).
    if (problem.error_indicator().size() ==
        model.triangulation().n_active_cells())
      data_out.add_data_vector(problem.error_indicator(), "error_indicator");
    ContactFields<dim> contact_fields(model.triangulation(), model.fe());
    if (contact_output)
      add_contact_fields(model,
                         problem,
                         *contact_output,
                         contact_fields,
                         data_out);

    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(mpi_communicator);
    const unsigned int rank =
      Utilities::MPI::this_mpi_process(mpi_communicator);
    if (n_ranks > 1)
      data_out.add_data_vector(cells.subdomain, "subdomain");
    // Simplices: one patch per cell; with P2 deal.II 9.4 writes quadratic
    // triangles and tetrahedra (VTK types 22 and 24: the fields at the
    // edge middles too). Curved cells (a second-order mesh): the patches'
    // points where the mapping puts them, inside the bodies too.
    if (model.curved_mapping() != nullptr)
      data_out.build_patches(model.mapping(),
                             parameters.finite_element.degree,
                             DataOut<dim>::curved_inner_cells);
    else if (model.triangulation().all_reference_cells_are_hyper_cube())
      data_out.build_patches(parameters.finite_element.degree);
    else
      data_out.build_patches(
        model.fe().reference_cell().template get_default_linear_mapping<dim>(),
        parameters.finite_element.degree);

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
      records.emplace_back(time, base + ".vtu");
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
      records.emplace_back(time, base + ".pvtu");
    }
    if (rank == 0)
      write_atomically(dir + "solution.pvd",
                       [&](std::ostream &out)
                       { DataOutBase::write_pvd_record(out, records); });
  }



  template class RunOutput<2>;
  template class RunOutput<3>;
} // namespace tribos
