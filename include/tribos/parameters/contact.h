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
     * A penalty written as `1e5` (absolute) or `100*E` / `E` (a multiple of
     * the smaller Young's modulus of the bodies of a pair, the paper's
     * convention; the result has units of stress per model length).
     */
    struct PenaltyValue
    {
      double value         = 0;
      bool   relative_to_E = false;
      bool   given         = false;

      /** Parse @p text for the parameter @p entry (for messages). */
      static PenaltyValue
      parse(const std::string &text, const std::string &entry);

      /** The penalty for a pair whose smaller Young's modulus is @p E. */
      double
      resolve(const double E) const
      {
        return relative_to_E ? value * E : value;
      }
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

      std::string  method;
      PenaltyValue normal_penalty;
      PenaltyValue tangential_penalty;
      double       friction_coefficient;
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
      std::string               tangent;
      std::string               passes;
      double                    search_distance;
      /** Master smoothing: "none" or "averaged normals" (2D). */
      std::string  smoothing;
      double       augmentation_tolerance;
      unsigned int max_augmentations;
      /** Status changes per increment beyond which a node chatters. */
      unsigned int chattering_flips;
      /** freeze, cutback or none. */
      std::string chattering_remedy;
      /**
       * Lagrange multipliers: the semismooth stick/slip parameter c_T; not
       * given: E / h of each slave node.
       */
      PenaltyValue friction_complementarity;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
      void
      check(const unsigned int dim) const;
    };
  } // namespace Parameters
} // namespace tribos

#endif
