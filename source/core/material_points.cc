/**
 * The converged state at the quadrature points: the deformation gradient
 * each material sees, for the outputs that evaluate the materials (the
 * VTU's stresses, the stored energy of dynamics).
 */

#include <tribos/core/f_bar.h>
#include <tribos/core/problem.h>

namespace tribos
{
  template <int dim>
  void
  Problem<dim>::for_each_material_point(const MaterialPointFunction &f) const
  {
    const bool         axisymmetric = parameters.finite_element.axisymmetric;
    const bool         f_bar        = parameters.finite_element.f_bar;
    const Vector      &u            = ghosted_displacement();
    const unsigned int n_q          = quadrature.size();
    FEValues<dim>      fe_values(*fe,
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
    FEValues<dim>      fe_centre(*fe,
                            QGauss<dim>(1),
                            update_values | update_gradients |
                              update_quadrature_points);
    std::vector<std::vector<Tensor<1, dim>>> gradients(
      n_q,
      std::vector<Tensor<1, dim>>(dim));
    std::vector<dealii::Vector<double>>      values(n_q,
                                               dealii::Vector<double>(dim));
    std::vector<std::vector<Tensor<1, dim>>> centre_gradients(
      1,
      std::vector<Tensor<1, dim>>(dim));
    std::vector<dealii::Vector<double>> centre_values(1,
                                                      dealii::Vector<double>(
                                                        dim));
    Tensor<2, 3>                        F3;

    for (const auto &cell : dof_handler.active_cell_iterators())
    {
      if (!cell->is_locally_owned())
        continue;
      fe_values.reinit(cell);
      fe_values.get_function_gradients(u, gradients);
      if (axisymmetric)
        fe_values.get_function_values(u, values);
      // F-bar: the material sees F scaled to the volume change of the
      // cell centre (axisymmetric: with the centre's hoop stretch), as in
      // the assembly.
      double J0 = 1;
      if (f_bar)
      {
        fe_centre.reinit(cell);
        fe_centre.get_function_gradients(u, centre_gradients);
        Tensor<2, dim> F0 = unit_symmetric_tensor<dim>();
        for (unsigned int c = 0; c < dim; ++c)
          F0[c] += centre_gradients[0][c];
        J0 = determinant(F0);
        if (axisymmetric)
        {
          fe_centre.get_function_values(u, centre_values);
          J0 *= 1. + centre_values[0](0) / fe_centre.quadrature_point(0)[0];
        }
      }
      const unsigned int n_history = n_history_variables(cell->material_id());
      const unsigned int offset    = history_offset[cell->active_cell_index()];
      for (unsigned int q = 0; q < n_q; ++q)
      {
        Tensor<2, dim> F = unit_symmetric_tensor<dim>();
        for (unsigned int c = 0; c < dim; ++c)
          F[c] += gradients[q][c];
        const double *history =
          n_history ? &history_old[offset + q * n_history] : nullptr;
        if (axisymmetric)
        {
          F3 = 0;
          for (unsigned int a = 0; a < 2; ++a)
            for (unsigned int b = 0; b < 2; ++b)
              F3[a][b] = F[a][b];
          F3[2][2] = 1. + values[q](0) / fe_values.quadrature_point(q)[0];
          if (f_bar)
            F3 *= FBar<3>::scale(F3, J0);
        }
        else if (f_bar)
          F *= FBar<dim>::scale(F, J0);
        f(cell, fe_values, q, F, F3, history);
      }
    }
  }

  template class Problem<2>;
  template class Problem<3>;
} // namespace tribos
