#include <tribos/base/text.h>
#include <tribos/parameters/time_stepping.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace tribos
{
  namespace
  {
    /** @p value as a user wrote it (shortest form, 6 digits). */
    std::string
    number(const double value)
    {
      std::ostringstream text;
      text << value;
      return text.str();
    }
  } // namespace



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
      prm.declare_entry(
        "Initial increment",
        "0",
        Text::non_negative_number(),
        "Size of the first increment (Abaqus *STATIC's initial time "
        "increment). 0: the nominal step, End time / Number of steps.");
      prm.declare_entry(
        "Minimum increment",
        "0",
        Text::non_negative_number(),
        "An increment cut below this stops the run (no convergence); an "
        "accuracy rejection (Maximum contact changes) never cuts "
        "below it. 0: 1e-12 of End time (round-off).");
      prm.declare_entry(
        "Maximum increment",
        "0",
        Text::non_negative_number(),
        "The increment grows (Growth factor) up to this size; every step's "
        "end is still landed on. 0: the nominal step, End time / Number of "
        "steps.");
      prm.declare_entry(
        "Output times",
        "",
        dealii::Patterns::Anything(),
        "Times in (0, End time], e.g. '1, 1.5, 3.5', that the increments "
        "land on besides the nominal steps' ends (Abaqus's *TIME POINTS). "
        "Each is a step of its own: the steps are the nominal steps' ends "
        "and these times in order, numbered from 1 (Output/Frequency, "
        "Output/Steps and Checkpoint every count them), and each listed "
        "time is always written.");
      prm.declare_entry(
        "Maximum contact changes",
        "0",
        dealii::Patterns::Double(0, 1),
        "Accuracy of a frictional path: the share of the active frictional "
        "contact nodes that may change in one increment, at least one node; "
        "a change is a node that closes (in stick or slip) or that begins "
        "to stick. Backward Euler gives such a node the tangential motion "
        "of the whole increment, also the part before it touched or stuck "
        "(a node of an indentation closes in slip where it should stick): "
        "the first-order error of the path. An increment with more changes "
        "is rejected and halved (never below Minimum increment, and not "
        "again where halving did not separate the nodes), and the "
        "increment grows only while the grown one would pass. Frictionless "
        "nodes do not count. 0: off (as Abaqus, convergence alone sizes "
        "the increments). 0.25 keeps the 2D ironing on 10 nominal steps "
        "within 0.2 % of 600 steps (6 % off without); off by default "
        "because on fine steps it only costs (the 3D ironing with "
        "multipliers on 0.02 steps: 48 rejections in 151 increments).");
      prm.declare_entry("Maximum cutbacks",
                        "6",
                        dealii::Patterns::Integer(0, 30),
                        "How often an increment may be halved in a row "
                        "before the run stops.");
      prm.declare_entry("Growth factor",
                        "2",
                        dealii::Patterns::Double(1, Text::largest_value),
                        "After an easy increment the next grows by this "
                        "factor, up to Maximum increment.");
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
      end_time            = prm.get_double("End time");
      n_steps             = prm.get_integer("Number of steps");
      initial_increment   = prm.get_double("Initial increment");
      minimum_increment   = prm.get_double("Minimum increment");
      maximum_increment   = prm.get_double("Maximum increment");
      max_contact_changes = prm.get_double("Maximum contact changes");
      output_times        = Text::parse_doubles(prm.get("Output times"),
                                         "Time stepping/Output times");
      max_cutbacks        = prm.get_integer("Maximum cutbacks");
      growth_factor       = prm.get_double("Growth factor");
      easy_iterations     = prm.get_integer("Easy iterations");
      growth_after = prm.get_integer("Growth after converged increments");
      extrapolate  = prm.get("Extrapolation") == "linear";
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
      resolve_increments(prm);
      prm.leave_subsection();
    }



    void
    TimeStepping::resolve_increments(dealii::ParameterHandler &prm)
    {
      const double nominal = end_time / n_steps;
      const auto   entry   = [&](const std::string &name)
      {
        return "Parameter <Time stepping/" + name + "> = <" + prm.get(name) +
               ">";
      };
      if (maximum_increment == 0)
        maximum_increment = nominal;
      if (minimum_increment == 0)
        minimum_increment = 1e-12 * end_time;
      if (initial_increment == 0)
        initial_increment =
          std::clamp(nominal,
                     std::min(minimum_increment, maximum_increment),
                     maximum_increment);
      AssertThrow(minimum_increment <= maximum_increment,
                  dealii::ExcMessage(
                    entry("Minimum increment") +
                    ": must not exceed the Maximum increment, " +
                    number(maximum_increment) + "."));
      AssertThrow(initial_increment >= minimum_increment &&
                    initial_increment <= maximum_increment,
                  dealii::ExcMessage(
                    entry("Initial increment") +
                    ": must lie between the Minimum and the Maximum "
                    "increment, [" +
                    number(minimum_increment) + ", " +
                    number(maximum_increment) + "]."));
      // The steps' ends: the nominal steps' and the output times, merged
      // where they coincide up to round-off.
      step_times.clear();
      for (unsigned int k = 1; k <= n_steps; ++k)
        step_times.push_back(k == n_steps ? end_time : k * nominal);
      for (const double t : output_times)
      {
        AssertThrow(t > 1e-12 * end_time && t <= end_time,
                    dealii::ExcMessage(
                      entry("Output times") + ": " + number(t) +
                      " must lie after t = 0 (by more than 1e-12 of End "
                      "time) and not after End time = " +
                      number(end_time) + "."));
        step_times.push_back(t);
      }
      std::sort(step_times.begin(), step_times.end());
      const double round_off = 1e-12 * end_time;
      step_times.erase(std::unique(step_times.begin(),
                                   step_times.end(),
                                   [round_off](const double a, const double b)
                                   { return b - a <= round_off; }),
                       step_times.end());
      step_times.back() = end_time;
    }



    bool
    TimeStepping::is_output_time(const unsigned int step) const
    {
      const double round_off = 1e-12 * end_time;
      return step >= 1 && step <= step_times.size() &&
             std::any_of(output_times.begin(),
                         output_times.end(),
                         [&](const double t) {
                           return std::abs(t - step_times[step - 1]) <=
                                  round_off;
                         });
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
