#include <tribos/contact/contact_pair.h>
#include <tribos/contact/rigid_surface_discretization.h>

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
  RigidSurfaceDiscretization<dim>::initialize(const ContactPair<dim> &pair)
  {
    require_linear_slave_faces(pair);
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
    std::string &)
  {
    NodeState &state = pair.current[k];
    state.result =
      NodeToRigid<dim>::evaluate(slave, rigid, *pair.enforcement, R, K);
    state.point = slave.position - scale(state.result.gap, state.result.normal);
    this->element_dofs(pair, k, -1, dofs);
    return {ElementOutcome::Kind::element,
            state.result.gap <= parameters.search_distance};
  }



  template class RigidSurfaceDiscretization<2>;
  template class RigidSurfaceDiscretization<3>;
} // namespace tribos
