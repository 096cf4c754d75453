#include <tribos/solver/time_integrator.h>

#include <deal.II/base/exceptions.h>

namespace tribos
{
  TimeIntegrator::TimeIntegrator(const Parameters::TimeStepping &parameters)
  {
    if (parameters.integrator == Parameters::Integrator::generalized_alpha)
    {
      // Chung and Hulbert (1993), eq. (25) and (17), (20): second order,
      // unconditionally stable, high-frequency dissipation set by rho_inf,
      // least low-frequency dissipation for it.
      const double rho = parameters.spectral_radius;
      am               = (2. * rho - 1.) / (rho + 1.);
      af               = rho / (rho + 1.);
      g                = 0.5 - am + af;
      b                = 0.25 * (1. - am + af) * (1. - am + af);
    }
    else
    {
      b = parameters.newmark_beta;
      g = parameters.newmark_gamma;
    }
  }



  void
  TimeIntegrator::set_step(const double step)
  {
    AssertThrow(step > 0,
                dealii::ExcMessage("TimeIntegrator: the step must be > 0."));
    dt = step;
  }
} // namespace tribos
