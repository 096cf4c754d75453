#include <tribos/base/text.h>
#include <tribos/contact/discretization/discretization_method.h>
#include <tribos/contact/enforcement/enforcement_method.h>
#include <tribos/parameters/contact.h>

#include <cmath>
#include <cstdlib>
#include <limits>

namespace tribos
{
  namespace Parameters
  {
    namespace
    {
      /** The entries of the pairs and their law: Pairs, Method, penalties,
       * friction. */
      void
      declare_law_entries(dealii::ParameterHandler &prm)
      {
        prm.declare_entry(
          "Pairs",
          "",
          dealii::Patterns::Anything(),
          "Contact pairs separated by ';': 'slave : master' or 'slave : master "
          ": key=value, ...'. slave is a list of boundary ids whose nodes are "
          "checked; master is a list of boundary ids (deformable master "
          "faces) or the name of a rigid surface. A list (e.g. '10, 11, 12') "
          "makes one connected surface: a node on the edge between two of its "
          "parts is one node, and master faces continue across that edge. "
          "Each slave id meets each master id in one pair only (a self "
          "pair 'a, b : a, b' holds a against b; two-pass adds 'b : a'). "
          "Per-pair keys: method, penalty, tangential penalty, mu, "
          "discretization (" +
            discretization_registry().join(" | ") +
            "). Example: '10 : 3 ; 4 : plate : mu=0.2 ; 3 : 10, 11, 12'.");
        // The methods that registered themselves
        // (source/contact/enforcement/), with their own descriptions.
        prm.declare_entry("Method",
                          "penalty",
                          dealii::Patterns::Selection(
                            enforcement_registry().selection_pattern()),
                          "Default enforcement of every pair. " +
                            enforcement_registry().documentation() + ".");
        // The discretizations that registered themselves
        // (source/contact/discretization/), with their own descriptions;
        // then their own entries (Mortar basis), where they were declared
        // before the registry (the order numbers the patterns of
        // --print-parameters json).
        prm.declare_entry(
          "Discretization",
          "node to segment",
          dealii::Patterns::Selection(
            discretization_registry().selection_pattern()),
          "Default discretization of every pair with a deformable master. " +
            discretization_registry().documentation() +
            ". Pairs with a rigid master are always node to rigid surface. "
            "Mortar is one-pass.");
        discretization_registry().declare_parameters(prm);
        prm.declare_entry(
          "Penalty factor",
          "100*E/h",
          dealii::Patterns::Anything(),
          "Normal penalty eps_N: 'k*E/h' (per slave node: k times the pair's "
          "contact modulus E over the node's element size h, its tributary "
          "length in 2D or the square root of its tributary area in 3D; "
          "independent of the length unit) or an absolute value in stress per "
          "length (model units; e.g. the paper's '10E' in mm is 10 x E "
          "written out). E = E_s E_m / (E_s + E_m) for two deformable bodies "
          "(the series modulus of the two sides, E/2 for equal materials) and "
          "E_s against a rigid surface (the limit E_m -> infinity), E_s and "
          "E_m the smallest Young's modulus of the bodies of each side. k is "
          "the contact stiffness relative to the element's own: penetration "
          "is about p h / (k E). 'k*E' without '/h' is refused.");
        prm.declare_entry("Tangential penalty factor",
                          "",
                          dealii::Patterns::Anything(),
                          "Tangential penalty eps_T (stick stiffness), same "
                          "syntax; empty means equal to the normal penalty.");
        prm.declare_entry(
          "Penalty formulation",
          "automatic",
          dealii::Patterns::Selection("automatic|primal|mixed"),
          "How Method = penalty is solved. automatic (the default): mixed for "
          "a pair of two deformable surfaces (not a self pair), primal against a rigid surface "
          "(whose exact smooth gap leaves Newton no faceted master to "
          "overshoot into) and on a self pair (where the mixed form's Newton "
          "stalled on a whole boundary as one surface); the log names each "
          "pair's choice. primal (the paper's (23)): the "
          "contact forces are functions of the displacements, t_N = eps_N "
          "<-g_N>. mixed: the same law with each slave node's traction as "
          "an unknown (a perturbed Lagrangian: g_N + t_N/eps_N = 0 while "
          "closed; in stick the slip equals the elastic slip (T - T_n)/"
          "eps_T), solved like Lagrange multipliers with the Normal and "
          "Friction complementarity parameters. The converged solution is "
          "the primal one; the iterates are not: Newton decides contact on "
          "the scale of those parameters (the body's E/h) instead of eps_N, "
          "so a node that a Newton step carries too deep does not come back "
          "with eps_N times its overshoot as a force. With a stiff penalty "
          "(100*E/h) and large sliding that overshoot made Newton diverge "
          "(parameters/ironing.prm: 172 cutbacks in 600 steps primal, none "
          "mixed). Costs the multiplier unknowns (dim per slave node).");
        prm.declare_entry(
          "Normal complementarity parameter",
          "E/h",
          dealii::Patterns::Anything(),
          "Lagrange multipliers and the penalty in mixed form: c of the "
          "semismooth normal decision "
          "(closed while t_N - c g_N >= 0) and the scale of the node's "
          "normal row c g_N (a solver parameter: it changes the iterates, "
          "never the converged solution). Same syntax as the penalties; the "
          "default E/h is the scale of the body's stiffness at the node. "
          "Much larger values make a penetration of round-off size decide "
          "the active set: with 100*E/h Newton cycled on the ironing "
          "(parameters/ironing.prm: 224 cutbacks and 20259 iterations in 600 "
          "steps, against none and 2362 with E/h).");
        prm.declare_entry(
          "Friction complementarity parameter",
          "E/h",
          dealii::Patterns::Anything(),
          "Lagrange multipliers and the penalty in mixed form: c_T of the "
          "semismooth stick/slip "
          "decision |T + c_T dg_T| <= mu max(0, t_N - c g_N) (a solver "
          "parameter: it changes the iterates, never the converged solution). "
          "Same syntax as the penalties; the default E/h is the scale of the "
          "body's stiffness at the node. Much larger values (e.g. 1000*E/h) "
          "let tiny slips flip the stick/slip state and can make Newton cycle "
          "on 3D frictional contact.");
        prm.declare_entry(
          "Friction coefficient",
          "0",
          Text::non_negative_number(),
          "Coulomb coefficient mu (>= 0); 0 is frictionless and "
          "stores no tangential state.");
      }



      /** The entries of the discretization and the search: Tangent,
       * Passes, smoothing, Search distance, ... */
      void
      declare_search_entries(dealii::ParameterHandler &prm)
      {
        prm.declare_entry("Tangent",
                          "consistent",
                          dealii::Patterns::Selection("consistent|paper"),
                          "consistent: exact derivative of the assembled "
                          "contact residual (projection, normal and metric "
                          "variations included); paper: the small-deformation "
                          "linearization (29)-(31) with those terms dropped.");
        prm.declare_entry("Passes",
                          "one-pass",
                          dealii::Patterns::Selection("one-pass|two-pass"),
                          "two-pass adds, for every deformable pair, the pair "
                          "with slave and master swapped; both carry half the "
                          "tributary area.");
        prm.declare_entry(
          "Master smoothing",
          "automatic",
          dealii::Patterns::Selection("automatic|none|averaged normals"),
          "automatic (the default): averaged normals for a pair whose "
          "deformable master is another surface (not a self pair) with "
          "Polynomial degree = 1, node to segment (in 3D falling back to the "
          "faces, with a warning, where a master vertex is shared by more "
          "faces, or a face surrounded by more nodes, than the smoothing "
          "takes) or 2D mortar; none for the other pairs (rigid, self, 3D "
          "mortar, quadratic elements). none: the master is its faces (piecewise linear in 2D, bilinear "
          "quadrilaterals or triangles in 3D). averaged normals: the normal "
          "field of each deformable master is interpolated between averaged "
          "nodal normals, so projection, gap and contact force stay "
          "continuous when a slave node crosses a master vertex (2D) or "
          "face edge (3D): no chattering between faces at kinks of a coarse "
          "or strongly deformed master, which makes Newton stall in large "
          "sliding. Node to segment in 2D and 3D (linear faces). With "
          "Discretization = mortar (2D, Q1) the integrals stay over the "
          "master's segments and only the nodal normal changes: the smoothed "
          "master normal averaged over the node's segments, instead of the "
          "slave's own normal, which tilts at the edge of the contact zone on "
          "a coarse curved slave; 3D mortar keeps the slave's normals.");
        prm.declare_entry("Search distance",
                          "0",
                          Text::non_negative_number(),
                          "Slave nodes farther than this from every master "
                          "face are not projected (open, no gap). 0: no "
                          "limit. Under MPI each process receives the master "
                          "nodes within this distance (plus three face "
                          "sizes; mortar: and five slave face sizes) of its "
                          "slave nodes at every search: with 0, the whole "
                          "master surface.");
      }



      /** The entries of the solution's policies: augmentation, chattering,
       * rigid surfaces. */
      void
      declare_policy_entries(dealii::ParameterHandler &prm)
      {
        prm.declare_entry("Augmentation tolerance",
                          "1e-4",
                          Text::non_negative_number(),
                          "augmented lagrangian: Uzawa updates of the "
                          "multipliers repeat an increment until every closed "
                          "slave node penetrates less than this fraction of "
                          "its local element size (sqrt or value of the "
                          "tributary area).");
        prm.declare_entry("Maximum augmentations",
                          "20",
                          dealii::Patterns::Integer(0),
                          "augmented lagrangian: multiplier updates per "
                          "increment at most; more are a non-convergence "
                          "(cutback).");
        prm.declare_entry("Chattering flips",
                          "2",
                          dealii::Patterns::Integer(1),
                          "A slave node whose contact status (open or "
                          "closed) changes more than this many times between "
                          "the Newton iterations of one increment while Newton "
                          "stalls (the residual not below half the best of "
                          "the increment) is chattering; changes while the "
                          "residual falls are the active set converging. "
                          "history.csv counts such nodes per increment "
                          "(chattering_nodes).");
        prm.declare_entry("Chattering remedy",
                          "freeze",
                          dealii::Patterns::Selection("freeze|cutback|none"),
                          "What happens when a node chatters (the log says "
                          "so): freeze (the node is held closed for the rest "
                          "of the increment; held nodes that end in tension "
                          "are released once and Newton goes on, a second "
                          "time the increment is cut back), cutback (the "
                          "increment is "
                          "abandoned and halved) or none (only counted).");
        prm.declare_entry(
          "Rigid surfaces",
          "",
          dealii::Patterns::Anything(),
          "Rigid analytic surfaces separated by ';': 'name : plane : px, py, pz "
          ": nx, ny, nz : motion', 'name : sphere : cx, cy, cz : R : motion', "
          "'name : cylinder : cx, cy, cz : R : ax, ay, az : motion' (3D; in 2D "
          "a cylinder is the circle 'cx, cy, 0 : R : motion'). The plane "
          "normal points towards the deformable body. motion: dim expressions "
          "in t, the translation of the surface.");
      }
    } // namespace



    void
    Contact::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      declare_law_entries(prm);
      declare_search_entries(prm);
      declare_policy_entries(prm);
      enforcement_registry().declare_parameters(prm);
      prm.leave_subsection();
    }



    void
    Contact::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      tangent         = prm.get("Tangent") == "paper" ? ContactTangent::paper :
                                                        ContactTangent::consistent;
      two_pass        = prm.get("Passes") == "two-pass";
      search_distance = prm.get_double("Search distance");
      {
        const std::string value = prm.get("Master smoothing");
        smoothing               = value == "none"      ? MasterSmoothing::none :
                                  value == "automatic" ? MasterSmoothing::automatic :
                                                         MasterSmoothing::averaged_normals;
      }
      augmentation_tolerance = prm.get_double("Augmentation tolerance");
      max_augmentations      = prm.get_integer("Maximum augmentations");
      chattering_flips       = prm.get_integer("Chattering flips");
      {
        const std::string remedy = prm.get("Chattering remedy");
        chattering_remedy = remedy == "freeze"  ? ChatteringRemedy::freeze :
                            remedy == "cutback" ? ChatteringRemedy::cutback :
                                                  ChatteringRemedy::none;
      }
      if (search_distance == 0)
        search_distance = std::numeric_limits<double>::infinity();

      const std::string default_method =
        parse_method(prm.get("Method"), "Contact/Method");
      const auto default_normal = PenaltyValue::parse(prm.get("Penalty factor"),
                                                      "Contact/Penalty factor");
      AssertThrow(default_normal.given,
                  dealii::ExcMessage(
                    "Parameter <Contact/Penalty factor> must not be empty."));
      auto default_tangential =
        PenaltyValue::parse(prm.get("Tangential penalty factor"),
                            "Contact/Tangential penalty factor");
      if (!default_tangential.given)
        default_tangential = default_normal;
      const double default_mu = prm.get_double("Friction coefficient");
      {
        const std::string value = prm.get("Penalty formulation");
        penalty_formulation     = value == "mixed" ? PenaltyFormulation::mixed :
                                  value == "automatic" ?
                                                     PenaltyFormulation::automatic :
                                                     PenaltyFormulation::primal;
      }
      enforcement_methods = enforcement_registry().parse_all(prm);
      normal_complementarity =
        PenaltyValue::parse(prm.get("Normal complementarity parameter"),
                            "Contact/Normal complementarity parameter");
      AssertThrow(normal_complementarity.given,
                  dealii::ExcMessage("Parameter <Contact/Normal "
                                     "complementarity parameter> must not be "
                                     "empty."));
      friction_complementarity =
        PenaltyValue::parse(prm.get("Friction complementarity parameter"),
                            "Contact/Friction complementarity parameter");
      AssertThrow(friction_complementarity.given,
                  dealii::ExcMessage("Parameter <Contact/Friction "
                                     "complementarity parameter> must not be "
                                     "empty (default: E/h)."));

      const std::string default_discretization =
        parse_discretization(prm.get("Discretization"),
                             "Contact/Discretization");
      discretization_methods = discretization_registry().parse_all(prm);

      rigid_surfaces = parse_rigid_surfaces(prm.get("Rigid surfaces"));
      const PairDefaults defaults{
        default_method,
        default_normal,
        default_tangential,
        PenaltyValue::parse(prm.get("Tangential penalty factor"), "").given,
        default_mu,
        default_discretization};
      pairs.clear();
      for (const auto &item : Text::split_top_level(prm.get("Pairs"), ';'))
        pairs.push_back(parse_pair(item, defaults, *this));
      check_interfaces(*this);
      prm.leave_subsection();
    }



    void
    Contact::resolve_pairs(const unsigned int dim, const unsigned int degree)
    {
      for (auto &pair : pairs)
      {
        const bool deformable_master = pair.rigid_surface.empty();
        // Mixed between two bodies. Not on a self pair: with the U's whole
        // boundary as one self surface (tests/verification/
        // self_contact.py) the mixed form's Newton never met its tolerance
        // once the slot closed (|R| at 1e-14, the increment cut to 1e-12),
        // where the primal form converges.
        const bool two_bodies = deformable_master && !pair.self_contact();
        pair.penalty_formulation =
          penalty_formulation != PenaltyFormulation::automatic ?
            penalty_formulation :
            (two_bodies ? PenaltyFormulation::mixed :
                          PenaltyFormulation::primal);
        // The smoothed master is of linear faces, assumes a master apart
        // from the slave, and is the discretization's to offer.
        const bool smoothable = deformable_master && !pair.self_contact() &&
                                degree == 1 &&
                                discretization_method(pair.discretization)
                                  ->smooths_master_by_default(dim);
        pair.smoothing_automatic = smoothing == MasterSmoothing::automatic;
        pair.smoothing           = smoothing != MasterSmoothing::automatic ?
                                     smoothing :
                                     (smoothable ? MasterSmoothing::averaged_normals :
                                                   MasterSmoothing::none);
      }
    }



    void
    Contact::check(const unsigned int dim) const
    {
      for (const auto &pair : pairs)
        discretization_method(pair.discretization)->check(pair, *this, dim);
      for (const auto &surface : rigid_surfaces)
      {
        AssertThrow(surface.motion.size() == dim,
                    dealii::ExcMessage(
                      "Parameter <Contact/Rigid surfaces>: surface <" +
                      surface.name + "> needs " + std::to_string(dim) +
                      " motion expressions."));
        if (surface.type == "plane")
          AssertThrow(surface.direction.size() == 3,
                      dealii::ExcMessage(
                        "Parameter <Contact/Rigid surfaces>: plane <" +
                        surface.name +
                        "> needs a normal with 3 components (z = 0 in "
                        "2D)."));
        if (surface.type == "cylinder" && dim == 3)
          AssertThrow(surface.direction.size() == 3,
                      dealii::ExcMessage(
                        "Parameter <Contact/Rigid surfaces>: cylinder <" +
                        surface.name +
                        "> needs an axis 'ax, ay, az' in "
                        "3D."));
      }
    }



    std::shared_ptr<const EnforcementMethod>
    Contact::enforcement_method(const std::string &name) const
    {
      const auto parsed = enforcement_methods.find(name);
      if (parsed != enforcement_methods.end())
        return parsed->second;
      return enforcement_registry().create_with_defaults(
        parse_method(name, "Contact/Method"));
    }



    std::shared_ptr<const DiscretizationMethod>
    Contact::discretization_method(const std::string &name) const
    {
      const std::string resolved =
        name.empty() ? discretization_registry().names().at(0) : name;
      const auto parsed = discretization_methods.find(resolved);
      if (parsed != discretization_methods.end())
        return parsed->second;
      return discretization_registry().create_with_defaults(
        parse_discretization(resolved, "Contact/Discretization"));
    }



    std::set<unsigned int>
    Contact::slave_boundary_ids() const
    {
      std::set<unsigned int> ids;
      for (const auto &pair : pairs)
      {
        ids.insert(pair.slave_boundary.begin(), pair.slave_boundary.end());
        if (two_pass && pair.rigid_surface.empty())
          ids.insert(pair.master_boundary.begin(), pair.master_boundary.end());
      }
      return ids;
    }
  } // namespace Parameters
} // namespace tribos
