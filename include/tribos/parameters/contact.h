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
      bool   two_pass;
      double search_distance;
      /** Contact/Master smoothing as written (automatic: each pair's
       * ContactPair::smoothing, set by resolve_pairs()). */
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
       * displacements; mixed: the tractions as unknowns; automatic: each
       * pair's ContactPair::penalty_formulation, set by resolve_pairs()). */
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
       * Decide, for each pair, the entries written `automatic` (the
       * defaults): Penalty formulation is mixed where the master is
       * another surface (primal against a rigid surface and on a self
       * pair); Master smoothing is averaged normals against another
       * surface's deformable master with linear elements (@p degree 1) where
       * the discretization offers it in @p dim dimensions (node to
       * segment; mortar in 2D) and none otherwise (rigid, self pairs, 3D
       * mortar, quadratic elements). doc/robustness.md gives the
       * measurements behind the rule. Explicit values are taken as
       * written.
       */
      void
      resolve_pairs(const unsigned int dim, const unsigned int degree);
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
