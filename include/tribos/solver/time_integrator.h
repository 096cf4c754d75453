#ifndef tribos_solver_time_integrator_h
#define tribos_solver_time_integrator_h

#include <tribos/parameters/time_stepping.h>

namespace tribos
{
  /**
   * The algebra of the implicit dynamic integrators on the displacement
   * form: Newmark's family and Chung and Hulbert's generalized-alpha
   * (J. Appl. Mech. 60, 1993), the latter with the forces averaged between
   * the ends of the step (Kuhl and Crisfield's form, which keeps the
   * material and contact laws at the end point t_n+1 and needs no
   * intermediate configuration):
   *
   *   M a_{n+1-alpha_m} + (1 - alpha_f) R(u_{n+1}, t_{n+1})
   *                      + alpha_f R(u_n, t_n) = 0,
   *
   * with R = f_int + f_contact - f_ext, x_{n+1-alpha} = (1 - alpha) x_{n+1}
   * + alpha x_n, and Newmark's relations between u, v and a. Newmark is
   * alpha_m = alpha_f = 0. The class only holds the coefficients and
   * evaluates the relations; the problem applies them to its vectors.
   */
  class TimeIntegrator
  {
  public:
    explicit TimeIntegrator(const Parameters::TimeStepping &parameters);

    /** Set the step size dt = t_{n+1} - t_n (> 0). */
    void
    set_step(const double dt);

    double
    alpha_m() const
    {
      return am;
    }

    double
    alpha_f() const
    {
      return af;
    }

    double
    beta() const
    {
      return b;
    }

    double
    gamma() const
    {
      return g;
    }

    /** The step size dt. */
    double
    step() const
    {
      return dt;
    }

    /** Weight of the forces at t_{n+1}: 1 - alpha_f. */
    double
    force_weight() const
    {
      return 1. - af;
    }

    /** d a_{n+1-alpha_m} / d u_{n+1}: (1 - alpha_m) / (beta dt^2), the
     * mass matrix's factor in the tangent. */
    double
    mass_weight() const
    {
      return (1. - am) / (b * dt * dt);
    }

    /** a_{n+1} from the displacement increment u_{n+1} - u_n and v_n,
     * a_n. */
    double
    acceleration(const double du, const double v, const double a) const
    {
      return (du - dt * v - dt * dt * (0.5 - b) * a) / (b * dt * dt);
    }

    /** a_{n+1-alpha_m}: the acceleration the inertia forces see. */
    double
    mid_acceleration(const double du, const double v, const double a) const
    {
      return (1. - am) * acceleration(du, v, a) + am * a;
    }

    /** v_{n+1} from v_n, a_n and a_{n+1}. */
    double
    velocity(const double v, const double a, const double a_new) const
    {
      return v + dt * ((1. - g) * a + g * a_new);
    }

    /**
     * A prescribed (Dirichlet) dof follows its boundary function, not
     * Newmark's recursion (which, started from a velocity that differs from
     * the prescribed rate, makes the dof's acceleration alternate and grow
     * linearly for beta = 1/4, gamma = 1/2): its velocity at t_{n+1} is the
     * mean rate of the step, du / dt, its acceleration the change of that
     * rate, (du / dt - v_n) / dt: exact for the piecewise linear motions of
     * a load history, bounded at its kinks.
     */
    double
    prescribed_acceleration(const double du, const double v) const
    {
      return (du / dt - v) / dt;
    }

    double
    prescribed_velocity(const double du) const
    {
      return du / dt;
    }

    /** d a_{n+1-alpha_m} / d u_{n+1} of a prescribed dof. */
    double
    prescribed_mass_weight() const
    {
      return (1. - am) / (dt * dt);
    }

  private:
    double am = 0, af = 0, b = 0.25, g = 0.5;
    double dt = 0;
  };
} // namespace tribos

#endif
