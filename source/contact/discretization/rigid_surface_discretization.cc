#include <tribos/contact/contact_pair.h>
#include <tribos/contact/discretization/rigid_surface_discretization.h>

#include <cmath>

namespace tribos
{
  template <int dim>
  RigidSurfaceDiscretization<dim>::RigidSurfaceDiscretization(
    const Parameters::Contact &parameters)
    : parameters(parameters)
  {
  }



  template <int dim>
  void
  RigidSurfaceDiscretization<dim>::initialize(const ContactPair<dim> &)
  {
    // Every slave surface works: linear faces with the integrals of their
    // functions as areas; quadratic segments (2D Q2 and P2) too, whose
    // functions integrate to h/6, 2h/3, h/6 (positive): with the dual
    // basis the mortar weighted gap against a plane is then the node's
    // gap times that area, the node-wise law. Six-node triangles through
    // their edge middles' virtual points (evaluate()).
  }



  template <int dim>
  void
  RigidSurfaceDiscretization<dim>::element_dofs(
    const ContactPair<dim> &pair,
    const unsigned int      k,
    const int,
    std::vector<types::global_dof_index> &dofs) const
  {
    const auto &node = pair.slave->nodes()[k];
    dofs.assign(node.dofs.begin(), node.dofs.end());
    for (const int v : node.edge)
      if (v >= 0)
        for (const auto dof : pair.slave->nodes()[v].dofs)
          dofs.push_back(dof);
    pair.append_unknown_dofs(k, dofs);
  }



  template <int dim>
  bool
  RigidSurfaceDiscretization<dim>::pair_node(ContactPair<dim>  &pair,
                                             const unsigned int k)
  {
    pair.current[k].paired = true;
    return false;
  }



  template <int dim>
  void
  RigidSurfaceDiscretization<dim>::begin_assembly(const ContactPair<dim> &pair,
                                                  const double            time,
                                                  const double committed_time)
  {
    rigid.surface   = pair.rigid.get();
    rigid.shift     = pair.rigid->translation(time);
    rigid.shift_old = pair.rigid->translation(committed_time);
  }



  template <int dim>
  ElementOutcome
  RigidSurfaceDiscretization<dim>::evaluate(
    ContactPair<dim>                     &pair,
    const unsigned int                    k,
    const SlaveInput                     &slave,
    double                               *R,
    double                               *K,
    std::vector<types::global_dof_index> &dofs,
    std::string                          &refusal)
  {
    NodeState  &state = pair.current[k];
    const auto &edge  = pair.slave->nodes()[k].edge;
    this->element_dofs(pair, k, -1, dofs);
    // A node the surface went through within the increment (deeper than
    // half its size): the increment is refused, so that the stepper cuts
    // it, rather than closing with zero force on the far side.
    const double size = std::pow(std::max(pair.area[k], 0.), 1. / (dim - 1));
    if (pair.rigid->passed_through(pair.old_slave_positions[k],
                                   rigid.shift_old,
                                   slave.position,
                                   rigid.shift,
                                   0.5 * size))
    {
      if (refusal.empty())
        refusal = "contact pair <" + pair.description.text +
                  ">: the rigid surface <" + pair.rigid->name() +
                  "> passed through a slave node within the increment "
                  "(tunnelling: outside at its start and end, through the "
                  "surface's interior between); the increment is cut";
      return {ElementOutcome::Kind::refused, false};
    }
    if (edge[0] < 0)
      state.result =
        NodeToRigid<dim>::evaluate(slave, rigid, *pair.enforcement, R, K);
    else
    {
      // The middle m of the edge a-b of six-node triangles: the contact
      // conditions hold for the modified basis's coefficient there (see
      // TriangleFace::modified_basis_alpha), the position of the virtual
      // point c_m x_m + c_a x_a + c_b x_b, and its force goes back to the
      // three nodes with the same factors. Its weight is the node's area
      // (A / 5 per face). With the vertices' own elements a uniform
      // pressure p gives the consistent loads of the quadratic face: 0 on
      // the vertices, p A / 3 on the middles.
      const double       alpha    = TriangleFace::modified_basis_alpha;
      const double       c[3]     = {1. / (1. - 2. * alpha),
                                     -alpha / (1. - 2. * alpha),
                                     -alpha / (1. - 2. * alpha)};
      const unsigned int nodes[3] = {k,
                                     static_cast<unsigned int>(edge[0]),
                                     static_cast<unsigned int>(edge[1])};
      SlaveInput         point    = slave;
      point.position              = {{0, 0, 0}};
      for (unsigned int a = 0; a < 3; ++a)
        point.position =
          point.position + scale(c[a], pair.slave_positions[nodes[a]]);
      const unsigned int n_unknowns = pair.enforcement->n_node_unknowns();
      const unsigned int n          = dim + n_unknowns;
      point_residual.resize(n);
      point_matrix.resize(n * n);
      state.result =
        NodeToRigid<dim>::evaluate(point,
                                   rigid,
                                   *pair.enforcement,
                                   point_residual.data(),
                                   K ? point_matrix.data() : nullptr);
      // Row or column i of the element: (node, component) or an unknown,
      // as a row or column of the point's element with its factor.
      const unsigned int n_out  = 3 * dim + n_unknowns;
      const auto         source = [&](const unsigned int i)
      {
        return i < 3 * dim ?
                 std::pair<unsigned int, double>{i % dim, c[i / dim]} :
                 std::pair<unsigned int, double>{i - 2 * dim, 1.};
      };
      for (unsigned int i = 0; i < n_out; ++i)
      {
        const auto [row, factor] = source(i);
        R[i]                     = factor * point_residual[row];
        if (K)
          for (unsigned int j = 0; j < n_out; ++j)
          {
            const auto [column, column_factor] = source(j);
            K[i * n_out + j] =
              factor * column_factor * point_matrix[row * n + column];
          }
      }
      state.point =
        point.position - scale(state.result.gap, state.result.normal);
      return {ElementOutcome::Kind::element,
              state.result.gap <= parameters.search_distance};
    }
    state.point = slave.position - scale(state.result.gap, state.result.normal);
    return {ElementOutcome::Kind::element,
            state.result.gap <= parameters.search_distance};
  }



  template class RigidSurfaceDiscretization<2>;
  template class RigidSurfaceDiscretization<3>;
} // namespace tribos
