#include <tribos/base/text.h>
#include <tribos/parameters/output.h>

#include <algorithm>

namespace tribos
{
  namespace Parameters
  {
    void
    Output::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry("Directory",
                        "output",
                        dealii::Patterns::Anything(),
                        "Created if missing; existing files are replaced.");
      prm.declare_entry("Frequency",
                        "1",
                        dealii::Patterns::Integer(0),
                        "Write VTU every this many steps (the nominal steps' "
                        "ends and Time stepping/Output times, in order); 0 "
                        "writes only the listed steps and the last one.");
      prm.declare_entry("Steps",
                        "",
                        dealii::Patterns::Anything(),
                        "Steps (1-based, as Frequency counts them) always "
                        "written, e.g. '44, 80'.");
      prm.declare_entry("Write VTU",
                        "true",
                        dealii::Patterns::Bool(),
                        "Write solution-NNNNN.vtu and solution.pvd.");
      prm.declare_entry("Probes",
                        "",
                        dealii::Patterns::Anything(),
                        "Points 'x, y(, z) ; ...': the displacement of the "
                        "mesh vertex nearest to each (in the reference "
                        "configuration) is written to history.csv as "
                        "probeK_ux, probeK_uy(, probeK_uz).");
      prm.declare_entry(
        "Checkpoint every",
        "0",
        dealii::Patterns::Integer(0),
        "Write a checkpoint after every this many steps (and after "
        "the last) into <Directory>/checkpoint-NNNNN (NNNNN: the step): the "
        "converged state (solution, plastic history, contact state, "
        "velocities, the stepping). 'tribos FILE.prm --restart DIR' goes "
        "on from it, also with another number of MPI processes. 0: never.");
      prm.leave_subsection();
    }



    void
    Output::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      directory = prm.get("Directory");
      frequency = prm.get_integer("Frequency");
      steps     = Text::parse_unsigned(prm.get("Steps"), "Output/Steps");
      write_vtu = prm.get_bool("Write VTU");
      probes.clear();
      for (const auto &item : Text::split_top_level(prm.get("Probes"), ';'))
        if (!Text::trim(item).empty())
          probes.push_back(Text::parse_doubles(item, "Output/Probes"));
      checkpoint_every = prm.get_integer("Checkpoint every");
      AssertThrow(!directory.empty(),
                  dealii::ExcMessage(
                    "Parameter <Output/Directory> must not be empty."));
      prm.leave_subsection();
    }



    bool
    Output::is_output_step(const unsigned int step,
                           const unsigned int n_steps) const
    {
      return step == n_steps || (frequency > 0 && step % frequency == 0) ||
             std::find(steps.begin(), steps.end(), step) != steps.end();
    }
  } // namespace Parameters
} // namespace tribos
