#ifndef tribos_parameters_time_stepping_h
#define tribos_parameters_time_stepping_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace tribos
{
  namespace Parameters
  {
    /** How time enters the equations (Time stepping/Integrator). */
    enum class Integrator
    {
      /** Quasi-static: time is a load parameter, no inertia. */
      quasi_static,
      /** Newmark's family with the given beta and gamma. */
      newmark,
      /** Chung-Hulbert generalized-alpha from the spectral radius. */
      generalized_alpha
    };

    /** The mass matrix of the dynamic integrators. */
    enum class MassMatrix
    {
      consistent,
      /** Row sums of the consistent one. */
      lumped
    };

    /** One initial velocity: body (material) id and its expressions. */
    struct InitialVelocity
    {
      unsigned int             body_id;
      std::vector<std::string> expressions;
    };

    /**
     * Subsection `Time stepping`: (pseudo-)time, load steps, cutbacks and,
     * for dynamics, the time integrator, the mass matrix and the initial
     * velocities.
     */
    struct TimeStepping
    {
      double end_time;
      /** Number of steps: the nominal steps. */
      unsigned int n_steps;
      /** The increments' bounds and first size, resolved (an entry's 0
       * replaced by its meaning). */
      double initial_increment;
      double minimum_increment;
      double maximum_increment;
      /** Output times as given. */
      std::vector<double> output_times;
      /**
       * The steps' ends, ascending, the last End time: the nominal steps'
       * ends merged with the Output times. The increments land on each; a
       * step is what the run reports (its console line, VTU, checkpoint).
       */
      std::vector<double> step_times;
      /** Maximum contact changes (0: off). */
      double       max_contact_changes;
      unsigned int max_cutbacks;
      double       growth_factor;
      unsigned int easy_iterations;
      unsigned int growth_after;
      /** Extrapolation = linear: an increment of a static run starts from
       * the last one's change, scaled by the increment sizes. */
      bool extrapolate;

      Integrator integrator;
      double     newmark_beta;
      double     newmark_gamma;
      double     spectral_radius;
      MassMatrix mass_matrix;
      /** Lumped mass moved off the contact surfaces' nodes to the other
       * nodes of their cells (Khenous, Laborde, Renard 2008). */
      bool                         contact_mass_removal;
      std::vector<InitialVelocity> initial_velocities;

      /** Newmark or generalized-alpha. */
      bool
      dynamic() const
      {
        return integrator != Integrator::quasi_static;
      }

      /** The number of steps, step_times.size(). */
      unsigned int
      n_step_ends() const
      {
        return step_times.size();
      }

      /** Whether step @p step (1-based) ends at one of the Output times. */
      bool
      is_output_time(const unsigned int step) const;

      /** Check the initial velocities against the dimension. */
      void
      check(const unsigned int dim) const;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

    private:
      /** Replace the increments' 0 entries by their meaning, check their
       * order, and merge the steps' ends (inside the subsection). */
      void
      resolve_increments(dealii::ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace tribos

#endif
