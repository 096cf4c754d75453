#include <tribos/core/material_state.h>
#include <tribos/material/material_model.h>

#include <type_traits>

namespace tribos
{
  template <int dim>
  MaterialState<dim>::MaterialState(const Parameters::AllParameters &parameters,
                                    const Triangulation<dim> &triangulation,
                                    const unsigned int n_quadrature_points,
                                    const MPI_Comm     mpi_communicator)
    : n_q_points(n_quadrature_points)
  {
    const auto &m = parameters.materials;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (!cell->is_artificial())
        body_ids.insert(cell->material_id());
    body_ids = Utilities::MPI::compute_set_union(body_ids, mpi_communicator);
    const types::material_id max_body = *body_ids.rbegin();
    m.check_body_count(max_body);
    // The same per-body data builds the dim materials and, for an
    // axisymmetric model, their 3D versions.
    const auto make = [&m](auto dimension, const unsigned int body)
    {
      using Lists = Parameters::Materials;
      // Every model's own lists first, then Poisson's ratio, Young's
      // modulus and Model: the order in which the lists were read for a
      // body before the registry, so that a file with several lists too
      // short reports the same one.
      for (const std::string &name : material_registry().names())
        m.model(name)->check_body(body);
      const double nu =
        Lists::for_body(m.poissons_ratios, body, "Poisson's ratio");
      const double E =
        Lists::for_body(m.youngs_moduli, body, "Young's modulus");
      const std::string &model = Lists::for_body(m.models, body, "Model");
      return m.model(model)->template create<decltype(dimension)::value>(body,
                                                                         E,
                                                                         nu);
    };
    // One material per body of the mesh, in the order of its id (a list's
    // error names an id the mesh has; the ids between them get nothing).
    ids.assign(body_ids.begin(), body_ids.end());
    for (const types::material_id body : ids)
      materials.push_back(make(std::integral_constant<int, dim>(), body));
    if (parameters.finite_element.axisymmetric)
    {
      // The most negative radius, relative to its cell's size, anywhere.
      double worst = 0, worst_x = 0;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto v : cell->vertex_indices())
            if (cell->vertex(v)[0] / cell->diameter() < worst)
            {
              worst   = cell->vertex(v)[0] / cell->diameter();
              worst_x = cell->vertex(v)[0];
            }
      const auto least = Utilities::MPI::min_max_avg(worst, mpi_communicator);
      worst_x =
        Utilities::MPI::broadcast(mpi_communicator, worst_x, least.min_index);
      AssertThrow(least.min >= -1e-10,
                  ExcMessage("Finite element/Axisymmetric = true needs "
                             "the mesh in x = r >= 0; vertex at x = " +
                             std::to_string(worst_x) + "."));
      for (const types::material_id body : ids)
        axisymmetric_materials.push_back(
          make(std::integral_constant<int, 3>(), body));
    }

    // History only where a material has memory: elastic bodies pay nothing.
    history_offset.assign(triangulation.n_active_cells(),
                          numbers::invalid_unsigned_int);
    unsigned int n_values = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        const unsigned int n = n_history_variables(cell->material_id());
        if (n > 0)
        {
          history_offset[cell->active_cell_index()] = n_values;
          n_values += n * n_q_points;
        }
      }
    history_old.assign(n_values, 0.);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && has_history(cell))
      {
        const unsigned int n = n_history_variables(cell->material_id());
        for (unsigned int q = 0; q < n_q_points; ++q)
        {
          double *history =
            &history_old[history_offset[cell->active_cell_index()] + q * n];
          if (axisymmetric_materials.empty())
            material(cell->material_id()).initialize_history(history);
          else
            axisymmetric_material(cell->material_id())
              .initialize_history(history);
        }
      }
    history_new = history_old;
  }



  template <int dim>
  bool
  MaterialState<dim>::any_history() const
  {
    bool any = false;
    for (const auto &m : materials)
      any = any || m->n_history_variables() > 0;
    for (const auto &m : axisymmetric_materials)
      any = any || m->n_history_variables() > 0;
    return any;
  }



  template class MaterialState<2>;
  template class MaterialState<3>;
} // namespace tribos
