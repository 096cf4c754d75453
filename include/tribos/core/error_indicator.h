#ifndef tribos_core_error_indicator_h
#define tribos_core_error_indicator_h

#include <tribos/contact/contact_handler.h>
#include <tribos/core/material_state.h>
#include <tribos/core/model.h>
#include <tribos/parameters/adaptivity.h>

#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

namespace tribos
{
  using namespace dealii;

  /**
   * Adaptivity's error indicator per active cell (own cells; zero
   * elsewhere): eta = (1 - a) eta_bulk + a eta_contact, each scaled to a
   * largest value of 1 over all processes, a = Contact indicator weight.
   *
   * eta_bulk: Kelly's jump of the gradient of the ghosted @p displacement
   * across the cells' inner faces (KellyErrorEstimator; a body's outer
   * faces add nothing), times the body's Young's modulus, so that a soft
   * and a stiff body compare in stress.
   *
   * eta_contact, per slave face from the current node states of its
   * pair: the jump of the pressure over the face's nodes divided by the
   * pair's largest pressure, plus 1 if the face has open and closed nodes
   * (the edge of the contact zone), plus 1 if an open node's gap is below
   * Closing gap factor times the face's size. It goes to the face's cell
   * and to the cells of the master faces its nodes are paired with (a
   * node-to-segment contact is as fine as its master). Collective.
   */
  template <int dim>
  dealii::Vector<float>
  error_indicator(const Parameters::Adaptivity        &parameters,
                  const Model<dim>                    &model,
                  const TrilinosWrappers::MPI::Vector &displacement,
                  const MaterialState<dim>            &materials,
                  const ContactHandler<dim>           *contact);

  /**
   * The contact zones of the current states (ContactZone): per own
   * active cell the size of its slave face with a closed node and of its
   * master face that such a node is closed on (0: none); per pair with
   * closed nodes their box. Collective.
   */
  template <int dim>
  ContactZone<dim>
  contact_zone(const Model<dim> &model, const ContactHandler<dim> &contact);

  /**
   * The number of slave faces (over all pairs and processes) on cells
   * below level @p maximum_level with a node that the current increment
   * closed (open in the committed state, closed in the current one), and
   * of such nodes closed on master faces of cells below that level: the
   * contact zone grew onto cells that the last adaptation left coarse.
   * Collective.
   */
  template <int dim>
  unsigned int
  n_faces_closed_below_level(const ContactHandler<dim> &contact,
                             const unsigned int         maximum_level,
                             const MPI_Comm             communicator);
} // namespace tribos

#endif
