#include <tribos/base/text.h>
#include <tribos/parameters/time_stepping.h>

namespace tribos
{
  namespace Parameters
  {
    void
    TimeStepping::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Time stepping");
      prm.declare_entry("End time",
                        "1",
                        Text::any_number(),
                        "Pseudo-time at the end of the run; boundary "
                        "expressions see it as t. > 0.");
      prm.declare_entry("Number of steps",
                        "10",
                        dealii::Patterns::Integer(1),
                        "Nominal load steps of equal size.");
      prm.declare_entry("Maximum cutbacks",
                        "6",
                        dealii::Patterns::Integer(0, 30),
                        "How often an increment may be halved in a row "
                        "before the run stops.");
      prm.declare_entry("Growth factor",
                        "2",
                        dealii::Patterns::Double(1, Text::largest_value),
                        "After an easy increment the next grows by this "
                        "factor, up to the nominal step.");
      prm.declare_entry("Easy iterations",
                        "5",
                        dealii::Patterns::Integer(1),
                        "An increment converged within this many Newton "
                        "iterations counts as easy.");
      prm.declare_entry("Growth after converged increments",
                        "4",
                        dealii::Patterns::Integer(0),
                        "After this many converged increments in a row the "
                        "next grows by Growth factor even if they were not "
                        "easy (cut increments whose Newton always needs "
                        "more than Easy iterations would otherwise never "
                        "regrow; a too large increment is simply cut "
                        "again). 0: only easy increments grow.");
      prm.declare_entry(
        "Extrapolation",
        "linear",
        dealii::Patterns::Selection("none|linear"),
        "Where Newton starts an increment of a static run. linear (as "
        "Abaqus/Standard does by default): the last converged state plus "
        "the last converged increment's change of every unknown, scaled by "
        "the ratio of the increment sizes; the first increment starts from "
        "the converged state. none: from the converged state. In a steady "
        "process the extrapolated state is nearly the solution (the paper's "
        "cylinder at 42k dofs, -np 2, GMRES: 174 Newton iterations, one "
        "cutback and 229 s with none, 82 and 57 s with linear, the same "
        "forces to 10 digits). Dynamics predicts with its integrator and "
        "ignores this.");
      prm.declare_entry(
        "Integrator",
        "static",
        dealii::Patterns::Selection("static|newmark|generalized alpha"),
        "static: quasi-static, time is a load parameter. newmark: inertia "
        "with Newmark's method (Newmark beta, Newmark gamma; 1/4, 1/2 is the "
        "energy-conserving average acceleration rule). generalized alpha: "
        "Chung-Hulbert with the forces averaged at t_n+1-alpha_f "
        "(Spectral radius). Dynamics needs Materials/Density > 0; time and "
        "End time are then physical times.");
      prm.declare_entry("Newmark beta",
                        "0.25",
                        Text::non_negative_number(),
                        "newmark: beta in (0, 0.5]; unconditionally stable "
                        "for beta >= gamma/2.");
      prm.declare_entry("Newmark gamma",
                        "0.5",
                        Text::non_negative_number(),
                        "newmark: gamma in [0.5, 1]; > 0.5 damps the high "
                        "frequencies (first order).");
      prm.declare_entry("Spectral radius",
                        "0.8",
                        dealii::Patterns::Double(0, 1),
                        "generalized alpha: rho_inf in [0, 1], the "
                        "amplification of the highest frequencies (1: no "
                        "dissipation, the average acceleration rule; 0: "
                        "annihilated in one step). Second-order accurate "
                        "for every value.");
      prm.declare_entry("Mass matrix",
                        "consistent",
                        dealii::Patterns::Selection("consistent|lumped"),
                        "consistent, or lumped (row sums).");
      prm.declare_entry(
        "Contact mass removal",
        "false",
        dealii::Patterns::Bool(),
        "true: the lumped mass of the nodes on contact surfaces (slave and "
        "deformable master) is moved to the other nodes of their cells, so "
        "that those nodes carry none: the impact oscillations of the contact "
        "force and the energy they spuriously gain or lose vanish (Khenous, "
        "Laborde, Renard 2008). Needs Mass matrix = lumped.");
      prm.declare_entry(
        "Initial velocity",
        "",
        dealii::Patterns::Anything(),
        "Dynamics: items 'body id : vx, vy(, vz)' separated by ';', "
        "expressions in x, y, z (reference coordinates). Bodies not named "
        "start at rest. Example: '1 : 0, -2'.");
      prm.leave_subsection();
    }



    void
    TimeStepping::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Time stepping");
      end_time        = prm.get_double("End time");
      n_steps         = prm.get_integer("Number of steps");
      max_cutbacks    = prm.get_integer("Maximum cutbacks");
      growth_factor   = prm.get_double("Growth factor");
      easy_iterations = prm.get_integer("Easy iterations");
      growth_after    = prm.get_integer("Growth after converged increments");
      extrapolate     = prm.get("Extrapolation") == "linear";
      const std::string integrator_name = prm.get("Integrator");
      integrator =
        integrator_name == "static" ?
          Integrator::quasi_static :
          (integrator_name == "newmark" ? Integrator::newmark :
                                          Integrator::generalized_alpha);
      newmark_beta    = prm.get_double("Newmark beta");
      newmark_gamma   = prm.get_double("Newmark gamma");
      spectral_radius = prm.get_double("Spectral radius");
      mass_matrix = prm.get("Mass matrix") == "lumped" ? MassMatrix::lumped :
                                                         MassMatrix::consistent;
      contact_mass_removal = prm.get_bool("Contact mass removal");
      AssertThrow(newmark_beta > 0 && newmark_beta <= 0.5,
                  dealii::ExcMessage(
                    "Parameter <Time stepping/Newmark beta> = <" +
                    prm.get("Newmark beta") +
                    ">: must lie in (0, 0.5] (beta = 0, the explicit "
                    "central difference rule, is not available)."));
      AssertThrow(newmark_gamma >= 0.5 && newmark_gamma <= 1,
                  dealii::ExcMessage(
                    "Parameter <Time stepping/Newmark gamma> = <" +
                    prm.get("Newmark gamma") +
                    ">: must lie in [0.5, 1] (gamma < 0.5 is unstable)."));
      AssertThrow(!contact_mass_removal || mass_matrix == MassMatrix::lumped,
                  dealii::ExcMessage(
                    "Parameter <Time stepping/Contact mass removal> = <true> "
                    "needs <Mass matrix> = <lumped>, not <" +
                    prm.get("Mass matrix") + ">."));
      initial_velocities.clear();
      const std::string entry = "Time stepping/Initial velocity";
      for (const auto &item :
           Text::split_top_level(prm.get("Initial velocity"), ';'))
      {
        const auto parts = Text::split_top_level(item, ':');
        AssertThrow(parts.size() == 2,
                    dealii::ExcMessage(
                      "Parameter <" + entry + ">: item <" + item +
                      "> must read 'body id : vx, vy(, vz)'."));
        const auto ids = Text::parse_unsigned(parts[0], entry);
        AssertThrow(ids.size() == 1,
                    dealii::ExcMessage("Parameter <" + entry +
                                       ">: expected one body id, got <" +
                                       parts[0] + ">."));
        for (const auto &v : initial_velocities)
          AssertThrow(v.body_id != ids[0],
                      dealii::ExcMessage("Parameter <" + entry +
                                         "> names body " +
                                         std::to_string(ids[0]) + " twice."));
        initial_velocities.push_back(
          {ids[0], Text::split_top_level(parts[1], ',')});
      }
      AssertThrow(initial_velocities.empty() || dynamic(),
                  dealii::ExcMessage(
                    "Parameter <" + entry +
                    "> is given, but <Time stepping/Integrator> = <static> "
                    "has no velocities: choose newmark or generalized "
                    "alpha."));
      AssertThrow(end_time > 0,
                  dealii::ExcMessage("Parameter <Time stepping/End time> = <" +
                                     prm.get("End time") + ">: must be > 0."));
      prm.leave_subsection();
    }



    void
    TimeStepping::check(const unsigned int dim) const
    {
      for (const auto &v : initial_velocities)
        AssertThrow(v.expressions.size() == dim,
                    dealii::ExcMessage(
                      "Parameter <Time stepping/Initial velocity>: body " +
                      std::to_string(v.body_id) + " has " +
                      std::to_string(v.expressions.size()) +
                      " expressions; Dimension = " + std::to_string(dim) +
                      " needs " + std::to_string(dim) + "."));
    }
  } // namespace Parameters
} // namespace tribos
