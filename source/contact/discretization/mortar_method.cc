#include <tribos/contact/discretization/discretization_method.h>
#include <tribos/contact/discretization/mortar_discretization.h>

namespace tribos
{
  namespace
  {
    /**
     * Contact/Discretization = mortar: its entry Mortar basis, its checks
     * and the MortarDiscretization of a pair. In a file of its own because
     * mortar_discretization.cc is near the 600 lines of a file.
     */
    class MortarMethod : public DiscretizationInBothDimensions<MortarMethod>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry(
          "Mortar basis",
          "dual",
          Patterns::Selection("dual|standard"),
          "Mortar: the functions that weight the gap and the traction of a "
          "slave node. dual: biorthogonal to the slave's shape functions, so "
          "each node's traction acts on that node alone (a diagonal slave "
          "matrix D); on a slave segment only partly overlapped by the "
          "master (at the master's end) they blend continuously into the "
          "standard functions, whose weights stay positive. standard: the "
          "slave's shape functions everywhere.");
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        dual = prm.get("Mortar basis") != "standard";
      }

      /** The smoothed master's nodal normals (2D): no tilt of the
       * slave's own normals at the edge of the contact zone on a coarse
       * curved slave (doc/mortar.md). */
      bool
      smooths_master_by_default(const unsigned int dim) const override
      {
        return dim == 2;
      }

      void
      check(const Parameters::ContactPair &pair,
            const Parameters::Contact     &contact,
            const unsigned int /*dim*/) const override
      {
        AssertThrow(!contact.two_pass,
                    ExcMessage("Contact pair <" + pair.text +
                               ">: Discretization = mortar is one-pass (it "
                               "passes the patch test with either side as "
                               "slave); set Contact/Passes = one-pass."));
      }

      template <int dim>
      std::unique_ptr<ContactDiscretization<dim>>
      make(const Parameters::ContactPair &pair,
           const Parameters::Contact     &parameters,
           const bool                     axisymmetric) const
      {
        const bool smoothed =
          pair.smoothing == Parameters::MasterSmoothing::averaged_normals;
        // The mortar's smoothed master normals exist in 2D.
        AssertThrow(!smoothed || dim == 2,
                    ExcMessage("Contact pair <" + pair.text +
                               ">: Contact/Master smoothing = averaged "
                               "normals with Discretization = mortar is "
                               "available in Dimension = 2 only (3D mortar "
                               "integrates over the faces with the slave's "
                               "averaged normals); allowed in 3D: node to "
                               "segment, or Master smoothing = none."));
        return std::make_unique<MortarDiscretization<dim>>(parameters,
                                                           dual,
                                                           smoothed && dim == 2,
                                                           axisymmetric);
      }

    private:
      /** Mortar basis = dual (else standard). */
      bool dual = true;
    };

    // Rank 1: the second of Contact/Discretization's choices.
    const DiscretizationRegistration mortar_registration =
      register_discretization<MortarMethod>(
        "mortar",
        "the gap, slip and force of each slave node are integrals over the "
        "overlap of its slave segments (faces in 3D) with the master "
        "segments, weighted by the node's multiplier function "
        "(segment-to-segment; passes the contact patch test)",
        1);
  } // namespace
} // namespace tribos
