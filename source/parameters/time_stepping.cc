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
                        dealii::Patterns::Double(),
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
                        dealii::Patterns::Double(1),
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
      AssertThrow(end_time > 0,
                  dealii::ExcMessage("Parameter <Time stepping/End time> = <" +
                                     prm.get("End time") + ">: must be > 0."));
      prm.leave_subsection();
    }
  } // namespace Parameters
} // namespace tribos
