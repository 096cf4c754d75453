#ifndef tribos_parameters_contact_h
#define tribos_parameters_contact_h

#include <tribos/parameters/contact_pair.h>

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace tribos
{
  class DiscretizationMethod;
  class EnforcementMethod;

  namespace Parameters
  {
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

    /** Contact/Penalty formulation. */
    enum class PenaltyFormulation
    {
      primal,
      mixed
    };

    /** Contact/Chattering remedy. */
    enum class ChatteringRemedy
    {
      freeze,
      cutback,
      none
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
      /** Lagrange multipliers: the semismooth parameters of the normal
       * condition (c) and of the stick/slip decision (c_T). */
      PenaltyValue normal_complementarity;
      /** How the penalty law is solved (primal: forces of the
       * displacements; mixed: the tractions as unknowns). */
      PenaltyFormulation penalty_formulation;
      PenaltyValue       friction_complementarity;
      /**
       * Every registered enforcement method with its own parameters, by
       * name: any of them may be a pair's (Contact/Method, method=).
       */
      std::map<std::string, std::shared_ptr<const EnforcementMethod>>
        enforcement_methods;

      /**
       * The enforcement method called @p name: from enforcement_methods or,
       * if parse_parameters() did not fill them (a Contact built by hand),
       * with its parameters' defaults; throws if none is called so.
       */
      std::shared_ptr<const EnforcementMethod>
      enforcement_method(const std::string &name) const;

      /**
       * Every registered discretization with its own parameters, by name:
       * any of them may be a pair's (Contact/Discretization,
       * discretization=).
       */
      std::map<std::string, std::shared_ptr<const DiscretizationMethod>>
        discretization_methods;

      /**
       * The discretization called @p name (empty: the first registered):
       * from discretization_methods or, if parse_parameters() did not fill
       * them (a Contact built by hand), with its parameters' defaults;
       * throws if none is called so.
       */
      std::shared_ptr<const DiscretizationMethod>
      discretization_method(const std::string &name) const;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
      void
      check(const unsigned int dim) const;
      /**
       * Not an entry: set by Adaptivity/Enable. Every pair hands its
       * hanging slave nodes to their parents (as pairs with multipliers
       * and mortar always do), also node to surface with a penalty: on a
       * refined curved surface a hanging vertex lies on the manifold while
       * its displacement follows the coarse neighbour's straight edge, and
       * a penalty would see the edge's sagitta as penetration.
       */
      bool carry_hanging_nodes = false;

      /** The boundary ids of every slave surface: the pairs' slaves and,
       * two-pass, their deformable masters too. */
      std::set<unsigned int>
      slave_boundary_ids() const;
    };
  } // namespace Parameters
} // namespace tribos

#endif
