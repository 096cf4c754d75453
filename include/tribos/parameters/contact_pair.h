#ifndef tribos_parameters_contact_pair_h
#define tribos_parameters_contact_pair_h

#include <set>
#include <string>
#include <vector>

namespace tribos
{
  namespace Parameters
  {
    /**
     * A penalty (or complementarity parameter) written as an absolute value
     * `1e5` (stress per model length) or as `k*E/h` (also `E/h`): k times
     * the pair's contact modulus E over the slave node's element size h
     * (its tributary length in 2D, the square root of its tributary area
     * in 3D). The relative form is free of the length unit: the same model
     * in mm or m gets the same penalty relative to its mesh. The old form
     * `k*E` (no h) is refused, because it is not: the same model in metres
     * would get a penalty 1000 times softer relative to its elements than
     * in millimetres.
     */
    struct PenaltyValue
    {
      double value    = 0;
      bool   per_node = false;
      bool   given    = false;

      /** Parse @p text for the parameter @p entry (for messages). */
      static PenaltyValue
      parse(const std::string &text, const std::string &entry);

      /**
       * The penalty at a slave node of element size @p h in a pair whose
       * contact modulus is @p E.
       */
      double
      resolve(const double E, const double h) const
      {
        return per_node ? value * E / h : value;
      }
    };

    struct Contact;

    /** Contact/Master smoothing. */
    enum class MasterSmoothing
    {
      none,
      averaged_normals,
      /** Decided per pair (Contact::resolve_pairs()). */
      automatic
    };

    /** Contact/Penalty formulation. */
    enum class PenaltyFormulation
    {
      primal,
      mixed,
      /** Decided per pair (Contact::resolve_pairs()). */
      automatic
    };

    /**
     * @p text, the name of a registered enforcement method (as written in
     * the parameter file: Contact/Method, a pair's method=); throws with a
     * message naming @p entry if it is none.
     */
    std::string
    parse_method(const std::string &text, const std::string &entry);

    /** A rigid analytic surface: plane, sphere or cylinder, moving in t. */
    struct RigidSurface
    {
      std::string name;
      /** "plane", "sphere" or "cylinder" (a circle in 2D). */
      std::string type;
      /** Plane: a point; sphere, cylinder: the centre (3 values, z = 0 in
       * 2D). */
      std::vector<double> point;
      /** Plane: normal pointing towards the deformable body. Cylinder: axis
       * (3D only). */
      std::vector<double> direction;
      double              radius = 0;
      /** dim expressions in t: the rigid translation of the surface. */
      std::vector<std::string> motion;
    };

    /**
     * One contact pair: slave surface, master surface or rigid surface. A
     * surface is the union of one or more boundary ids (like an Abaqus
     * surface made of several facet sets), so that a corner between two
     * boundary parts is one node of one connected surface.
     */
    struct ContactPair
    {
      std::set<unsigned int> slave_boundary;
      /** Master boundary ids; empty if the master is rigid. */
      std::set<unsigned int> master_boundary;
      /** Name of the rigid master surface (empty if deformable). */
      std::string rigid_surface;

      /** The item as written, for messages. */
      std::string text;
      /** The enforcement method's name (Contact/Method, method=). */
      std::string  method;
      PenaltyValue normal_penalty;
      PenaltyValue tangential_penalty;
      double       friction_coefficient;
      /**
       * The discretization's name (Contact/Discretization,
       * discretization=; a rigid master's resolved); empty: the first
       * registered one.
       */
      std::string discretization;
      /** How this pair's penalty is solved, if its method is penalty
       * (Contact/Penalty formulation, resolved: never automatic once
       * Contact::resolve_pairs() has run). */
      PenaltyFormulation penalty_formulation = PenaltyFormulation::primal;
      /** This pair's master smoothing (Contact/Master smoothing, resolved:
       * never automatic). */
      MasterSmoothing smoothing = MasterSmoothing::none;
      /** The smoothing was chosen by Master smoothing = automatic: a
       * master that the smoothing cannot take (a vertex shared by too many
       * faces) falls back to its faces with a warning instead of an
       * error. */
      bool smoothing_automatic = false;

      /** Self-contact: the slave surface is its own master (the same
       * boundary ids on both sides). */
      bool
      self_contact() const
      {
        return rigid_surface.empty() && slave_boundary == master_boundary;
      }
    };

    /** The defaults of a pair: the entries of the subsection Contact. */
    struct PairDefaults
    {
      std::string  method;
      PenaltyValue normal_penalty, tangential_penalty;
      /** Whether Tangential penalty factor was given (else a pair's own
       * penalty is its tangential one too). */
      bool        tangential_given;
      double      friction_coefficient;
      std::string discretization;
    };

    /**
     * @p text, the name of a registered discretization (as written in the
     * parameter file); throws with a message naming @p entry if it is
     * none.
     */
    std::string
    parse_discretization(const std::string &text, const std::string &entry);

    /** The surfaces of Contact/Rigid surfaces = @p text. */
    std::vector<RigidSurface>
    parse_rigid_surfaces(const std::string &text);

    /** The pair of the Contact/Pairs item @p item with @p defaults, its
     * master one of the rigid surfaces of @p contact or boundary ids. */
    ContactPair
    parse_pair(const std::string  &item,
               const PairDefaults &defaults,
               const Contact      &contact);

    /**
     * Refuse pairs of @p contact that repeat an interface: an exact
     * duplicate would apply its contact twice; so would two passes (the
     * pairs, the swapped ones Contact/Passes = two-pass adds, a self pair
     * for all of its ids in both directions) whose slave ids share one and
     * whose master ids share one, or that name the same rigid surface;
     * the same interface written twice with slave and master swapped,
     * with a method that holds the gap exactly, holds the same gap twice;
     * a self-contact pair with such a method would either hold each gap
     * twice or, one side only, let the other side through
     * (doc/self_contact.md). Needs Contact::two_pass parsed.
     */
    void
    check_interfaces(const Contact &contact);
  } // namespace Parameters
} // namespace tribos

#endif
