#ifndef tribos_contact_mortar_integrals_h
#define tribos_contact_mortar_integrals_h

#include <tribos/contact/element/mortar_element.h>
#include <tribos/contact/element/mortar_element_3d.h>

#include <type_traits>

namespace tribos
{
  /**
   * What the mortar element of a slave node j integrates, in AD numbers of
   * its nodes' coordinates (the slave nodes of its input, then the master
   * nodes, dim each, then the node's unknowns): the seeded positions,
   * D_jk = int Phi_j N_k on the slave nodes, M_jl = int Phi_j N_l on the
   * master nodes, and the unnormalized nodal normal n_j (out of the
   * slave). Mortar2D and Mortar3D fill it; internal::finish_mortar() turns
   * it into the node's weighted gap, slip and rows.
   */
  template <int dim>
  struct MortarIntegrals
  {
    using Input = std::conditional_t<dim == 2, MortarInput, MortarInput3D>;
    static constexpr unsigned int max_slave_nodes = Input::max_slave_nodes;
    static constexpr unsigned int max_master_nodes =
      dim == 2 ? max_mortar_master_nodes : max_mortar_master_nodes_3d;

    /**
     * The positions of @p input seeded, with @p n_unknowns unknowns of
     * the enforcement after them; D, M and n_j zero. Only the entries in
     * use are set: an element keeps one object per thread (the arrays
     * hold some 600 AD numbers, whose construction zeroes 2 MB; once per
     * element evaluation that was a third of the 3D mortar's time).
     * Without @p with_derivatives the numbers are constants: an
     * evaluation of the residual only (no K) computes the same values
     * without the derivatives' work.
     */
    void
    reset(const Input       &element_input,
          const unsigned int n_unknowns,
          const bool         with_derivatives)
    {
      input                       = &element_input;
      derivatives                 = with_derivatives;
      n_s                         = element_input.n_slave_nodes;
      n_m                         = element_input.n_master_nodes;
      n_displacements             = dim * (n_s + n_m);
      n_out                       = n_displacements + n_unknowns;
      const unsigned int n_seeded = derivatives ? n_out : 0;
      for (unsigned int i = 0; i < n_s; ++i)
        xs[i] = internal::seed<dim>(element_input.xs[i], dim * i, n_seeded);
      for (unsigned int l = 0; l < n_m; ++l)
        xm[l] =
          internal::seed<dim>(element_input.xm[l], dim * (n_s + l), n_seeded);
      const ContactAD zero(0.);
      for (unsigned int i = 0; i < n_s; ++i)
        D[i] = zero;
      for (unsigned int l = 0; l < n_m; ++l)
        M[l] = zero;
      normal_j = {{zero, zero, zero}};
    }

    /** This thread's object, reset() for @p element_input. */
    static MortarIntegrals &
    for_element(const Input       &element_input,
                const unsigned int n_unknowns,
                const bool         with_derivatives)
    {
      static thread_local MortarIntegrals integrals;
      integrals.reset(element_input, n_unknowns, with_derivatives);
      return integrals;
    }

    const Input *input = nullptr;
    /** Whether the numbers carry derivatives (see reset()). */
    bool            derivatives = true;
    unsigned int    n_s = 0, n_m = 0, n_displacements = 0, n_out = 0;
    Vec3<ContactAD> xs[max_slave_nodes], xm[max_master_nodes];
    ContactAD       D[max_slave_nodes], M[max_master_nodes];
    Vec3<ContactAD> normal_j;
  };



  namespace internal
  {
    /**
     * The end of every mortar element (2D and 3D): from its @p integrals,
     * the weight w_j = sum D, the weighted gap and slip, and the
     * enforcement's rows through finish_weighted(); @p paired is set to
     * whether w_j reaches the input's min_weight (if not, R and K are
     * untouched); @p weighted_point gets x_j + (weighted master point -
     * weighted slave point), the node's contact point.
     */
    template <int dim>
    ContactPointResult
    finish_mortar(const SlaveInput       &slave,
                  const Enforcement<dim> &enforcement,
                  MortarIntegrals<dim>   &integrals,
                  double                 *R,
                  double                 *K,
                  bool                   &paired,
                  Vec3<double>           &weighted_point);
  } // namespace internal
} // namespace tribos

#endif
