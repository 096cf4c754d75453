#include <tribos/contact/contact_pair.h>
#include <tribos/contact/discretization/contact_discretization.h>
#include <tribos/contact/discretization/discretization_method.h>

namespace tribos
{
  Registry<DiscretizationMethod> &
  discretization_registry()
  {
    // Constructed on first use: the discretizations' files register during
    // static initialization, in no defined order.
    static Registry<DiscretizationMethod> discretizations("discretization");
    return discretizations;
  }



  template <int dim>
  void
  ContactDiscretization<dim>::stencil(const ContactPair<dim> &,
                                      const unsigned int         k,
                                      std::vector<unsigned int> &nodes) const
  {
    nodes.assign(1, k);
  }



  template <int dim>
  void
  ContactDiscretization<dim>::insert_couplings(
    const ContactPair<dim>                          &pair,
    const unsigned int                               k,
    const unsigned int                               face,
    std::set<std::pair<unsigned int, unsigned int>> &into)
  {
    into.insert({k, face});
    for (const unsigned int g : pair.master->faces()[face].neighbours)
      into.insert({k, g});
  }



  template <int dim>
  void
  ContactDiscretization<dim>::add_couplings(
    const ContactPair<dim>          &pair,
    const AffineConstraints<double> &constraints,
    DynamicSparsityPattern          &dsp) const
  {
    std::vector<types::global_dof_index> dofs;
    for (const auto &[k, f] : pair.couplings)
    {
      element_dofs(pair, k, f, dofs);
      constraints.add_entries_local_to_global(dofs, dsp, false);
    }
  }



  template <int dim>
  void
  ContactDiscretization<dim>::used_couplings(
    const ContactPair<dim>                          &pair,
    const unsigned int                               k,
    std::set<std::pair<unsigned int, unsigned int>> &into) const
  {
    const int face = pair.current[k].face;
    if (face >= 0)
      insert_couplings(pair, k, face, into);
  }



  template <int dim>
  void
  ContactDiscretization<dim>::element_dofs(
    const ContactPair<dim>               &pair,
    const unsigned int                    k,
    const int                             face,
    std::vector<types::global_dof_index> &dofs) const
  {
    const auto &slave_dofs = pair.slave->nodes()[k].dofs;
    dofs.assign(slave_dofs.begin(), slave_dofs.end());
    if (pair.master && face >= 0)
    {
      const auto &f = pair.master->faces()[face];
      for (unsigned int i = 0; i < f.n_nodes(); ++i)
        for (const auto dof : pair.master->nodes()[f.node(i)].dofs)
          dofs.push_back(dof);
    }
    pair.append_unknown_dofs(k, dofs);
  }



  template <int dim>
  void
  require_linear_slave_faces(const ContactPair<dim> &pair)
  {
    // On Q2 the surface's middle nodes need the quadratic segments of the
    // mortar element.
    AssertThrow(!pair.slave->quadratic(),
                ExcMessage("Contact pair <" + pair.description.text +
                           ">: Finite element/Polynomial degree = 2 needs "
                           "Contact/Discretization = mortar or a rigid "
                           "surface; node-to-segment contact works on the "
                           "linear faces of Polynomial degree = 1."));
  }



  template <int dim>
  std::unique_ptr<ContactDiscretization<dim>>
  create_discretization(const Parameters::ContactPair &description,
                        const Parameters::Contact     &parameters,
                        const bool                     axisymmetric)
  {
    return parameters.discretization_method(description.discretization)
      ->template create<dim>(description, parameters, axisymmetric);
  }



  template class ContactDiscretization<2>;
  template class ContactDiscretization<3>;
  template void
  require_linear_slave_faces(const ContactPair<2> &);
  template void
  require_linear_slave_faces(const ContactPair<3> &);
  template std::unique_ptr<ContactDiscretization<2>>
  create_discretization(const Parameters::ContactPair &,
                        const Parameters::Contact &,
                        const bool);
  template std::unique_ptr<ContactDiscretization<3>>
  create_discretization(const Parameters::ContactPair &,
                        const Parameters::Contact &,
                        const bool);
} // namespace tribos
