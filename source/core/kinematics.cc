#include <tribos/core/f_bar.h>
#include <tribos/core/kinematics.h>

#include <deal.II/base/quadrature_lib.h>

namespace tribos
{
  template <int dim>
  Kinematics<dim>::Kinematics(const Mapping<dim>       &mapping,
                              const FiniteElement<dim> &fe,
                              const Quadrature<dim>    &quadrature)
    : fe_values(mapping,
                fe,
                quadrature,
                update_values | update_gradients | update_quadrature_points |
                  update_JxW_values)
    , component(fe.n_dofs_per_cell())
    , gradients(quadrature.size(), std::vector<Tensor<1, dim>>(dim))
  {
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      component[i] = fe.system_to_component_index(i).first;
  }



  template <int dim>
  void
  Kinematics<dim>::reinit(const CellIterator &cell, const Vector &u)
  {
    fe_values.reinit(cell);
    fe_values.get_function_gradients(u, gradients);
  }



  template <int dim>
  std::unique_ptr<Kinematics<dim>>
  StandardKinematics<dim>::clone() const
  {
    return std::make_unique<StandardKinematics<dim>>(
      this->fe_values.get_mapping(),
      this->fe_values.get_fe(),
      this->fe_values.get_quadrature());
  }



  template <int dim>
  Tensor<2, dim>
  StandardKinematics<dim>::deformation_gradient(const unsigned int q) const
  {
    Tensor<2, dim> F = unit_symmetric_tensor<dim>();
    for (unsigned int c = 0; c < dim; ++c)
      F[c] += this->gradients[q][c];
    return F;
  }



  template <int dim>
  MaterialPoint<dim>
  StandardKinematics<dim>::material_point(const unsigned int q) const
  {
    MaterialPoint<dim> point;
    point.F = deformation_gradient(q);
    return point;
  }



  template <int dim>
  void
  StandardKinematics<dim>::add_stress(const unsigned int            q,
                                      const Tensor<2, dim>         &P,
                                      const Tensor<4, dim>         *A,
                                      const dealii::Vector<double> *force,
                                      CellTerms                    &cell) const
  {
    const auto        &fe_values = this->fe_values;
    const auto        &component = this->component;
    const unsigned int n_dofs    = component.size();
    const double       JxW       = fe_values.JxW(q);
    for (unsigned int i = 0; i < n_dofs; ++i)
    {
      const unsigned int    ci     = component[i];
      const Tensor<1, dim> &grad_i = fe_values.shape_grad(i, q);
      double                r      = P[ci] * grad_i;
      if (force != nullptr)
      {
        r -= (*force)[ci] * fe_values.shape_value(i, q);
        if (cell.external != nullptr)
          (*cell.external)(i) +=
            (*force)[ci] * fe_values.shape_value(i, q) * JxW;
      }
      cell.rhs(i) -= r * JxW;

      if (A != nullptr)
      {
        // A_{ci l cj n} grad_i[l]: the row of A seen by dof i.
        Tensor<2, dim> row;
        for (unsigned int l = 0; l < dim; ++l)
          row += grad_i[l] * (*A)[ci][l];
        for (unsigned int j = (cell.upper_only ? i : 0); j < n_dofs; ++j)
          cell.matrix(i, j) +=
            (row[component[j]] * fe_values.shape_grad(j, q)) * JxW;
      }
    }
  }



  template <int dim>
  void
  StandardKinematics<dim>::add_point(const unsigned int    q,
                                     const PointData<dim> &point,
                                     CellTerms            &cell) const
  {
    Tensor<2, dim> P;
    Tensor<4, dim> A;
    point.materials.material(point.body)
      .evaluate(deformation_gradient(q),
                point.old_history,
                point.new_history,
                P,
                cell.with_matrix ? &A : nullptr);
    add_stress(q, P, cell.with_matrix ? &A : nullptr, point.force, cell);
  }



  template <int dim>
  FBarKinematics<dim>::FBarKinematics(const Mapping<dim>       &mapping,
                                      const FiniteElement<dim> &fe,
                                      const Quadrature<dim>    &quadrature)
    : StandardKinematics<dim>(mapping, fe, quadrature)
    , centre(mapping,
             fe,
             fe.reference_cell().template get_gauss_type_quadrature<dim>(1),
             update_values | update_gradients | update_quadrature_points)
    , centre_gradients(1, std::vector<Tensor<1, dim>>(dim))
  {
  }



  template <int dim>
  std::unique_ptr<Kinematics<dim>>
  FBarKinematics<dim>::clone() const
  {
    return std::make_unique<FBarKinematics<dim>>(
      this->fe_values.get_mapping(),
      this->fe_values.get_fe(),
      this->fe_values.get_quadrature());
  }



  template <int dim>
  void
  FBarKinematics<dim>::reinit(
    const typename Kinematics<dim>::CellIterator &cell,
    const typename Kinematics<dim>::Vector       &u)
  {
    Kinematics<dim>::reinit(cell, u);
    centre.reinit(cell);
    centre.get_function_gradients(u, centre_gradients);
    F0 = unit_symmetric_tensor<dim>();
    for (unsigned int c = 0; c < dim; ++c)
      F0[c] += centre_gradients[0][c];
    J0 = determinant(F0);
  }



  template <int dim>
  MaterialPoint<dim>
  FBarKinematics<dim>::material_point(const unsigned int q) const
  {
    MaterialPoint<dim> point;
    point.F = this->deformation_gradient(q);
    point.F *= FBar<dim>::scale(point.F, J0);
    return point;
  }



  template <int dim>
  void
  FBarKinematics<dim>::add_point(const unsigned int    q,
                                 const PointData<dim> &point,
                                 CellTerms            &cell) const
  {
    const Tensor<2, dim> F = this->deformation_gradient(q);
    const double         s = FBar<dim>::scale(F, J0);
    Tensor<2, dim>       P, P_eff;
    Tensor<4, dim>       A, dP_dF, dP_dF0;
    point.materials.material(point.body)
      .evaluate(s * F,
                point.old_history,
                point.new_history,
                P,
                cell.with_matrix ? &A : nullptr);
    FBar<dim>::effective(F,
                         F0,
                         s,
                         P,
                         cell.with_matrix ? &A : nullptr,
                         P_eff,
                         dP_dF,
                         dP_dF0);
    this->add_stress(q,
                     P_eff,
                     cell.with_matrix ? &dP_dF : nullptr,
                     point.force,
                     cell);
    if (!cell.with_matrix)
      return;
    // Coupling through the centre's volume change.
    const auto        &fe_values = this->fe_values;
    const auto        &component = this->component;
    const unsigned int n_dofs    = component.size();
    const double       JxW       = fe_values.JxW(q);
    for (unsigned int i = 0; i < n_dofs; ++i)
    {
      const unsigned int    ci     = component[i];
      const Tensor<1, dim> &grad_i = fe_values.shape_grad(i, q);
      Tensor<2, dim>        centre_row;
      for (unsigned int l = 0; l < dim; ++l)
        centre_row += grad_i[l] * dP_dF0[ci][l];
      for (unsigned int j = 0; j < n_dofs; ++j)
        cell.matrix(i, j) +=
          (centre_row[component[j]] * centre.shape_grad(j, 0)) * JxW;
    }
  }



  std::unique_ptr<Kinematics<2>>
  AxisymmetricKinematics::clone() const
  {
    return std::make_unique<AxisymmetricKinematics>(fe_values.get_mapping(),
                                                    fe_values.get_fe(),
                                                    fe_values.get_quadrature());
  }



  void
  AxisymmetricKinematics::reinit(const CellIterator &cell, const Vector &u)
  {
    Kinematics<2>::reinit(cell, u);
    values.resize(fe_values.n_quadrature_points, dealii::Vector<double>(2));
    fe_values.get_function_values(u, values);
  }



  double
  AxisymmetricKinematics::volume_weight(const unsigned int q) const
  {
    return fe_values.JxW(q) * 2. * numbers::PI *
           fe_values.quadrature_point(q)[0];
  }



  Tensor<2, 3>
  AxisymmetricKinematics::deformation_gradient(const unsigned int q) const
  {
    // F = [[F_rr, F_rz, 0], [F_zr, F_zz, 0], [0, 0, 1 + u_r / r]].
    Tensor<2, 3> F3;
    for (unsigned int a = 0; a < 2; ++a)
      for (unsigned int b = 0; b < 2; ++b)
        F3[a][b] = (a == b ? 1. : 0.) + gradients[q][a][b];
    F3[2][2] = 1. + values[q](0) / fe_values.quadrature_point(q)[0];
    return F3;
  }



  MaterialPoint<2>
  AxisymmetricKinematics::material_point(const unsigned int q) const
  {
    MaterialPoint<2> point;
    point.F3           = deformation_gradient(q);
    point.axisymmetric = true;
    for (unsigned int a = 0; a < 2; ++a)
      for (unsigned int b = 0; b < 2; ++b)
        point.F[a][b] = point.F3[a][b];
    return point;
  }



  double
  AxisymmetricKinematics::hoop(const unsigned int i, const unsigned int q) const
  {
    return component[i] == 0 ?
             fe_values.shape_value(i, q) / fe_values.quadrature_point(q)[0] :
             0.;
  }



  void
  AxisymmetricKinematics::add_stress(const unsigned int            q,
                                     const Tensor<2, 3>           &P3,
                                     const Tensor<4, 3>           *A3,
                                     const dealii::Vector<double> *force,
                                     CellTerms                    &cell) const
  {
    const unsigned int n_dofs = component.size();
    const double       radius = fe_values.quadrature_point(q)[0];
    const double       JxW    = volume_weight(q);
    Tensor<2, 3>       row3;
    for (unsigned int i = 0; i < n_dofs; ++i)
    {
      const unsigned int  ci     = component[i];
      const Tensor<1, 2> &grad_i = fe_values.shape_grad(i, q);
      const double        hoop_i = hoop(i, q);
      double              r =
        P3[ci][0] * grad_i[0] + P3[ci][1] * grad_i[1] + P3[2][2] * hoop_i;
      if (force != nullptr)
      {
        r -= (*force)[ci] * fe_values.shape_value(i, q);
        if (cell.external != nullptr)
          (*cell.external)(i) +=
            (*force)[ci] * fe_values.shape_value(i, q) * JxW;
      }
      cell.rhs(i) -= r * JxW;
      if (A3 == nullptr)
        continue;
      row3 = grad_i[0] * (*A3)[ci][0] + grad_i[1] * (*A3)[ci][1] +
             hoop_i * (*A3)[2][2];
      for (unsigned int j = 0; j < n_dofs; ++j)
      {
        const unsigned int  cj     = component[j];
        const Tensor<1, 2> &grad_j = fe_values.shape_grad(j, q);
        double value = row3[cj][0] * grad_j[0] + row3[cj][1] * grad_j[1];
        if (cj == 0)
          value += row3[2][2] * fe_values.shape_value(j, q) / radius;
        cell.matrix(i, j) += value * JxW;
      }
    }
  }



  void
  AxisymmetricKinematics::add_point(const unsigned int  q,
                                    const PointData<2> &point,
                                    CellTerms          &cell) const
  {
    Tensor<2, 3> P3;
    Tensor<4, 3> A3;
    point.materials.axisymmetric_material(point.body)
      .evaluate(deformation_gradient(q),
                point.old_history,
                point.new_history,
                P3,
                cell.with_matrix ? &A3 : nullptr);
    add_stress(q, P3, cell.with_matrix ? &A3 : nullptr, point.force, cell);
  }



  AxisymmetricFBarKinematics::AxisymmetricFBarKinematics(
    const Mapping<2>       &mapping,
    const FiniteElement<2> &fe,
    const Quadrature<2>    &quadrature)
    : AxisymmetricKinematics(mapping, fe, quadrature)
    , centre(mapping,
             fe,
             fe.reference_cell().template get_gauss_type_quadrature<2>(1),
             update_values | update_gradients | update_quadrature_points)
    , centre_gradients(1, std::vector<Tensor<1, 2>>(2))
    , centre_values(1, dealii::Vector<double>(2))
  {
  }



  std::unique_ptr<Kinematics<2>>
  AxisymmetricFBarKinematics::clone() const
  {
    return std::make_unique<AxisymmetricFBarKinematics>(
      fe_values.get_mapping(),
      fe_values.get_fe(),
      fe_values.get_quadrature());
  }



  void
  AxisymmetricFBarKinematics::reinit(const CellIterator &cell, const Vector &u)
  {
    AxisymmetricKinematics::reinit(cell, u);
    // The volume change of the centre includes its hoop stretch.
    centre.reinit(cell);
    centre.get_function_gradients(u, centre_gradients);
    centre.get_function_values(u, centre_values);
    centre_radius = centre.quadrature_point(0)[0];
    F3_0          = 0;
    for (unsigned int a = 0; a < 2; ++a)
      for (unsigned int b = 0; b < 2; ++b)
        F3_0[a][b] = (a == b ? 1. : 0.) + centre_gradients[0][a][b];
    F3_0[2][2] = 1. + centre_values[0](0) / centre_radius;
    J0         = determinant(F3_0);
  }



  MaterialPoint<2>
  AxisymmetricFBarKinematics::material_point(const unsigned int q) const
  {
    MaterialPoint<2> point = AxisymmetricKinematics::material_point(q);
    point.F3 *= FBar<3>::scale(point.F3, J0);
    return point;
  }



  void
  AxisymmetricFBarKinematics::add_point(const unsigned int  q,
                                        const PointData<2> &point,
                                        CellTerms          &cell) const
  {
    const Tensor<2, 3> F3 = deformation_gradient(q);
    const double       s3 = FBar<3>::scale(F3, J0);
    Tensor<2, 3>       P3, P3_eff;
    Tensor<4, 3>       A3, dP3_dF, dP3_dF0;
    point.materials.axisymmetric_material(point.body)
      .evaluate(s3 * F3,
                point.old_history,
                point.new_history,
                P3,
                cell.with_matrix ? &A3 : nullptr);
    FBar<3>::effective(F3,
                       F3_0,
                       s3,
                       P3,
                       cell.with_matrix ? &A3 : nullptr,
                       P3_eff,
                       dP3_dF,
                       dP3_dF0);
    add_stress(q,
               P3_eff,
               cell.with_matrix ? &dP3_dF : nullptr,
               point.force,
               cell);
    if (!cell.with_matrix)
      return;
    // Coupling through the centre's volume change, whose virtual
    // deformation gradient has the hoop entry too.
    const unsigned int n_dofs = component.size();
    const double       JxW    = volume_weight(q);
    Tensor<2, 3>       centre_row3;
    for (unsigned int i = 0; i < n_dofs; ++i)
    {
      const unsigned int  ci     = component[i];
      const Tensor<1, 2> &grad_i = fe_values.shape_grad(i, q);
      centre_row3 = grad_i[0] * dP3_dF0[ci][0] + grad_i[1] * dP3_dF0[ci][1] +
                    hoop(i, q) * dP3_dF0[2][2];
      for (unsigned int j = 0; j < n_dofs; ++j)
      {
        const unsigned int  cj     = component[j];
        const Tensor<1, 2> &grad_j = centre.shape_grad(j, 0);
        double              value =
          centre_row3[cj][0] * grad_j[0] + centre_row3[cj][1] * grad_j[1];
        if (cj == 0)
          value += centre_row3[2][2] * centre.shape_value(j, 0) / centre_radius;
        cell.matrix(i, j) += value * JxW;
      }
    }
  }



  template <int dim>
  std::unique_ptr<Kinematics<dim>>
  create_kinematics(const Parameters::FiniteElement &parameters,
                    const Mapping<dim>              &mapping,
                    const FiniteElement<dim>        &fe,
                    const Quadrature<dim>           &quadrature)
  {
    if constexpr (dim == 2)
      if (parameters.axisymmetric)
      {
        if (parameters.f_bar)
          return std::make_unique<AxisymmetricFBarKinematics>(mapping,
                                                              fe,
                                                              quadrature);
        return std::make_unique<AxisymmetricKinematics>(mapping,
                                                        fe,
                                                        quadrature);
      }
    if (parameters.f_bar)
      return std::make_unique<FBarKinematics<dim>>(mapping, fe, quadrature);
    return std::make_unique<StandardKinematics<dim>>(mapping, fe, quadrature);
  }



  template class Kinematics<2>;
  template class Kinematics<3>;
  template class StandardKinematics<2>;
  template class StandardKinematics<3>;
  template class FBarKinematics<2>;
  template class FBarKinematics<3>;
  template std::unique_ptr<Kinematics<2>>
  create_kinematics(const Parameters::FiniteElement &,
                    const Mapping<2> &,
                    const FiniteElement<2> &,
                    const Quadrature<2> &);
  template std::unique_ptr<Kinematics<3>>
  create_kinematics(const Parameters::FiniteElement &,
                    const Mapping<3> &,
                    const FiniteElement<3> &,
                    const Quadrature<3> &);
} // namespace tribos
