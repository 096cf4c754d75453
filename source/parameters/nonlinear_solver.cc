#include <tribos/base/text.h>
#include <tribos/parameters/nonlinear_solver.h>

namespace tribos
{
  namespace Parameters
  {
    void
    NonlinearSolver::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Nonlinear solver");
      prm.declare_entry("Maximum iterations",
                        "20",
                        dealii::Patterns::Integer(1),
                        "Newton iterations allowed per increment before the "
                        "increment is cut back (an iterate whose residual "
                        "meets its tolerance still gets up to two solves "
                        "that confirm its update).");
      prm.declare_entry(
        "Residual tolerance",
        "1e-8",
        dealii::Patterns::Double(0, 0.1),
        "Converged when |R| <= tol * max(|R| at the start of "
        "the increment, |f_int - f_ext| over all dofs "
        "including the constrained ones, i.e. the "
        "reactions) + Absolute residual tolerance. At most 0.1: "
        "a relative tolerance near 1 accepts the first "
        "iterate, far from equilibrium.");
      prm.declare_entry("Absolute residual tolerance",
                        "1e-12",
                        Text::non_negative_number(),
                        "Floor of the residual test, in force units.");
      prm.declare_entry("Increment tolerance",
                        "1e-8",
                        dealii::Patterns::Double(0, 0.1),
                        "Converged also requires |du| <= tol * |u increment "
                        "of the step| (or |du| <= tol * |u| if larger); at "
                        "most 0.1.");
      prm.declare_entry("Line search",
                        "true",
                        dealii::Patterns::Bool(),
                        "Backtracking on the residual norm (Armijo).");
      prm.declare_entry("Maximum line search steps",
                        "6",
                        dealii::Patterns::Integer(0, 30),
                        "Halvings of the step length at most.");
      prm.declare_entry(
        "Penetration limit",
        "0.5",
        Text::non_negative_number(),
        "The most a Newton step may deepen a contact node's penetration, "
        "in units of its element size (0: no limit). A step that would "
        "carry a node deeper is shortened to the length at which the first "
        "node reaches the limit (the gaps at the full step, evaluated "
        "without the bulk, interpolated): a body held by a few contact "
        "nodes (a load-controlled first touch) then sinks into the master "
        "step by step instead of through it in one.");
      prm.declare_entry("Check tangent",
                        "false",
                        dealii::Patterns::Bool(),
                        "Compare the assembled tangent with central finite "
                        "differences of the residual in every iteration "
                        "(columns of the contact dofs and a sample of the "
                        "others) and print the relative error. Slow; for "
                        "verification and debugging (serial runs).");
      prm.declare_entry(
        "Tangent shift",
        "1e-12",
        dealii::Patterns::Double(0, 1e-3),
        "Before every linear solve each diagonal entry of the tangent is "
        "multiplied by 1 + this (0: off). The residual is left alone, so "
        "the solution is the same, and a regular tangent changes by this "
        "relative amount only; a singular one gets a defined solve: a body "
        "that the first iterate rests on one frictionless node can turn "
        "about a point of a side held only normal to the load, and "
        "without the shift the solver's round-off chose that turn (the "
        "dof numbering decided between 10 and 44 Newton iterations of the "
        "load-controlled Hertz 2D).");
      prm.declare_entry(
        "Stabilization factor",
        "0",
        Text::non_negative_number(),
        "0: off. Otherwise every dof gets a spring to an anchor, its "
        "position at the start of the increment, of stiffness factor * E / "
        "h^2 * (integral of its shape function) (E of the body, h the cell "
        "diameter): it holds bodies that are free until contact closes "
        "(force control, initially apart). An increment is converged only "
        "when the springs carry at most Stabilization limit of the load; "
        "until then the anchors are moved to the converged iterate and "
        "Newton goes on (a pseudo-transient continuation), so the final "
        "state is an equilibrium of the loads alone up to that fraction. "
        "The ratio is written to history.csv (stabilization_ratio) and its "
        "largest value to summary.txt.");
      prm.declare_entry(
        "Stabilization limit",
        "1e-3",
        dealii::Patterns::Double(0, 1),
        "Largest accepted ratio of the stabilization forces to the load at "
        "the end of an increment: the largest magnitude of the springs' "
        "resultant on one body over the largest of the magnitudes of the "
        "applied force resultant (tractions and body forces) and of the "
        "reaction resultant of each Dirichlet condition.");
      prm.declare_entry("Maximum stabilization relaxations",
                        "100",
                        dealii::Patterns::Integer(0),
                        "Re-anchorings of the springs per increment at "
                        "most before the increment counts as not converged "
                        "(cut back).");
      prm.leave_subsection();
    }



    void
    NonlinearSolver::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Nonlinear solver");
      max_iterations     = prm.get_integer("Maximum iterations");
      residual_tolerance = prm.get_double("Residual tolerance");
      absolute_residual_tolerance =
        prm.get_double("Absolute residual tolerance");
      increment_tolerance   = prm.get_double("Increment tolerance");
      line_search           = prm.get_bool("Line search");
      max_line_search_steps = prm.get_integer("Maximum line search steps");
      check_tangent         = prm.get_bool("Check tangent");
      penetration_limit     = prm.get_double("Penetration limit");
      tangent_shift         = prm.get_double("Tangent shift");
      stabilization         = prm.get_double("Stabilization factor");
      stabilization_limit   = prm.get_double("Stabilization limit");
      max_stabilization_relaxations =
        prm.get_integer("Maximum stabilization relaxations");
      prm.leave_subsection();
    }
  } // namespace Parameters
} // namespace tribos
