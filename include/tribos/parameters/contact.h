#ifndef tribos_parameters_contact_h
#define tribos_parameters_contact_h

#include <deal.II/base/parameter_handler.h>

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

    /** How a pair enforces contact (Contact/Method). */
    enum class EnforcementMethod
    {
      penalty,
      lagrange_multiplier,
      augmented_lagrangian
    };

    /** The parameter file's name of @p method. */
    std::string
    to_string(const EnforcementMethod method);

    /** @p text as a method (as written in the parameter file); throws
     * with a message naming @p entry if it is none. */
    EnforcementMethod
    parse_method(const std::string &text, const std::string &entry);

    /** Contact/Tangent. */
    enum class ContactTangent
    {
      consistent,
      paper
    };

    /** Contact/Master smoothing. */
    enum class MasterSmoothing
    {
      none,
      averaged_normals
    };

    /** Contact/Discretization: how a pair's contact is integrated. */
    enum class Discretization
    {
      node_to_segment,
      mortar
    };

    /** Contact/Mortar basis: the multiplier (weight) functions of mortar. */
    enum class MortarBasis
    {
      dual,
      standard
    };

    /** Contact/Chattering remedy. */
    enum class ChatteringRemedy
    {
      freeze,
      cutback,
      none
    };

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
      std::string       text;
      EnforcementMethod method;
      PenaltyValue      normal_penalty;
      PenaltyValue      tangential_penalty;
      double            friction_coefficient;
      Discretization    discretization = Discretization::node_to_segment;
    };

    /**
     * Subsection `Contact`: the pairs and how they are enforced. Method,
     * penalties and friction coefficient are defaults for every pair and
     * can be overridden per pair, so that a single --set switches a scene.
     */
    struct Contact
    {
      std::vector<ContactPair>  pairs;
      std::vector<RigidSurface> rigid_surfaces;
      ContactTangent            tangent;
      /** Contact/Passes = two-pass. */
      bool            two_pass;
      double          search_distance;
      MasterSmoothing smoothing;
      double          augmentation_tolerance;
      unsigned int    max_augmentations;
      /** Status changes per increment beyond which a node chatters. */
      unsigned int     chattering_flips;
      ChatteringRemedy chattering_remedy;
      /** Lagrange multipliers: the semismooth stick/slip parameter c_T. */
      PenaltyValue friction_complementarity;
      MortarBasis  mortar_basis;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
      void
      check(const unsigned int dim) const;
      /** The boundary ids of every slave surface: the pairs' slaves and,
       * two-pass, their deformable masters too. */
      std::set<unsigned int>
      slave_boundary_ids() const;
    };
  } // namespace Parameters
} // namespace tribos

#endif
