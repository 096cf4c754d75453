#include <tribos/core/symmetry_constraints.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace tribos
{
  namespace
  {
    /** Normals closer than this (the cosine of 18 degrees) are one
     * direction. */
    constexpr double same_direction = 0.95;

    /** Drop the round-off of @p v's entries against its largest one: a
     * plane normal to x should constrain u_x alone. */
    template <int dim>
    Tensor<1, dim>
    clean(Tensor<1, dim> v)
    {
      v /= v.norm();
      for (unsigned int d = 0; d < dim; ++d)
        if (std::abs(v[d]) < 1e-13)
          v[d] = 0;
      return v / v.norm();
    }

    /** u . @p n = 0 on the dofs @p dofs: the component of n's largest
     * entry follows the others. */
    template <int dim>
    void
    constrain_normal(const std::array<types::global_dof_index, dim> &dofs,
                     const Tensor<1, dim>                           &n,
                     AffineConstraints<double> &constraints)
    {
      unsigned int k = 0;
      for (unsigned int d = 1; d < dim; ++d)
        if (std::abs(n[d]) > std::abs(n[k]))
          k = d;
      if (!constraints.can_store_line(dofs[k]))
        return;
      constraints.add_line(dofs[k]);
      for (unsigned int d = 0; d < dim; ++d)
        if (d != k && n[d] != 0)
          constraints.add_entry(dofs[k], dofs[d], -n[d] / n[k]);
    }

    /** u parallel to @p t on the dofs @p dofs (3D): the component of t's
     * largest entry is free, the others follow it. */
    template <int dim>
    void
    constrain_tangent(const std::array<types::global_dof_index, dim> &dofs,
                      const Tensor<1, dim>                           &t,
                      AffineConstraints<double> &constraints)
    {
      unsigned int k = 0;
      for (unsigned int d = 1; d < dim; ++d)
        if (std::abs(t[d]) > std::abs(t[k]))
          k = d;
      for (unsigned int d = 0; d < dim; ++d)
        if (d != k && constraints.can_store_line(dofs[d]))
        {
          constraints.add_line(dofs[d]);
          if (t[d] != 0)
            constraints.add_entry(dofs[d], dofs[k], t[d] / t[k]);
        }
    }
  } // namespace



  template <int dim>
  void
  make_symmetry_constraints(const Mapping<dim>                 &mapping,
                            const DoFHandler<dim>              &dof_handler,
                            const std::set<types::boundary_id> &ids,
                            AffineConstraints<double>          &constraints)
  {
    const auto &fe   = dof_handler.get_fe();
    const auto &base = fe.base_element(0);
    // The normal of a face at a support point: the reference face's normal
    // n^ mapped covariantly, n ~ J^-T n^ (exact on curved cells too).
    FEValues<dim> fe_values(mapping,
                            fe,
                            Quadrature<dim>(base.get_unit_support_points()),
                            update_inverse_jacobians);
    struct SupportPoint
    {
      std::array<types::global_dof_index, dim> dofs;
      std::vector<Tensor<1, dim>>              normals;
    };
    // By the support point's first dof.
    std::map<types::global_dof_index, SupportPoint> points;
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
    {
      if (cell->is_artificial())
        continue;
      bool on_symmetry = false;
      for (const auto f : cell->face_indices())
        on_symmetry = on_symmetry || (cell->face(f)->at_boundary() &&
                                      ids.count(cell->face(f)->boundary_id()));
      if (!on_symmetry)
        continue;
      fe_values.reinit(cell);
      cell->get_dof_indices(cell_dofs);
      for (const auto f : cell->face_indices())
      {
        if (!cell->face(f)->at_boundary() ||
            ids.count(cell->face(f)->boundary_id()) == 0)
          continue;
        const ReferenceCell  kind = cell->reference_cell();
        const Tensor<1, dim> reference =
          kind.template unit_normal_vectors<dim>(f);
        const Point<dim> corner =
          kind.template vertex<dim>(kind.face_to_cell_vertices(f, 0, 1));
        for (unsigned int b = 0; b < base.n_dofs_per_cell(); ++b)
        {
          // On the reference face's plane (FE_SimplexP answers
          // has_support_on_face() with true for every dof).
          if (std::abs(reference * (base.unit_support_point(b) - corner)) >
              1e-12)
            continue;
          const auto     K = fe_values.inverse_jacobian(b);
          Tensor<1, dim> normal;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              normal[j] += reference[i] * K[i][j];
          auto &point = points[cell_dofs[fe.component_to_system_index(0, b)]];
          for (unsigned int c = 0; c < dim; ++c)
            point.dofs[c] = cell_dofs[fe.component_to_system_index(c, b)];
          point.normals.push_back(normal / normal.norm());
        }
      }
    }

    for (const auto &[first, point] : points)
    {
      // The directions: normals within 18 degrees of one are averaged.
      std::vector<Tensor<1, dim>> directions;
      for (const auto &n : point.normals)
      {
        auto same = std::find_if(directions.begin(),
                                 directions.end(),
                                 [&n](const Tensor<1, dim> &d)
                                 { return d * n / d.norm() > same_direction; });
        if (same == directions.end())
          directions.push_back(n);
        else
          *same += n;
      }
      for (auto &d : directions)
        d = clean(d);
      // Three directions span space unless nearly coplanar.
      bool fixed = directions.size() >= dim;
      if (dim == 3 && directions.size() == 3)
      {
        Tensor<2, dim> m;
        for (unsigned int a = 0; a < dim; ++a)
          m[a] = directions[a];
        fixed = std::abs(determinant(m)) > 0.05;
      }
      if (fixed)
      {
        for (unsigned int d = 0; d < dim; ++d)
          if (constraints.can_store_line(point.dofs[d]))
            constraints.add_line(point.dofs[d]);
      }
      else if (directions.size() == 1)
        constrain_normal<dim>(point.dofs, directions[0], constraints);
      else if constexpr (dim == 3)
      {
        // Two planes (or three nearly coplanar normals: the two furthest
        // apart): u along their intersection.
        unsigned int a = 0, b = 1;
        for (unsigned int i = 0; i < directions.size(); ++i)
          for (unsigned int j = i + 1; j < directions.size(); ++j)
            if (std::abs(directions[i] * directions[j]) <
                std::abs(directions[a] * directions[b]))
            {
              a = i;
              b = j;
            }
        constrain_tangent<dim>(point.dofs,
                               clean(cross_product_3d(directions[a],
                                                      directions[b])),
                               constraints);
      }
    }
  }



  template void
  make_symmetry_constraints(const Mapping<2> &,
                            const DoFHandler<2> &,
                            const std::set<types::boundary_id> &,
                            AffineConstraints<double> &);
  template void
  make_symmetry_constraints(const Mapping<3> &,
                            const DoFHandler<3> &,
                            const std::set<types::boundary_id> &,
                            AffineConstraints<double> &);
} // namespace tribos
