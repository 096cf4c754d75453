#include <tribos/base/text.h>
#include <tribos/parameters/parallel.h>

#include <string>

namespace tribos
{
  namespace Parameters
  {
    void
    Parallel::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Parallel");
      prm.declare_entry(
        "Mesh",
        "distributed",
        dealii::Patterns::Selection("shared|distributed"),
        "How the mesh is held under MPI. shared: every process holds the "
        "whole mesh and owns a part of it (memory grows with the mesh on "
        "every process). distributed: every process holds only the cells it "
        "owns and one layer of ghost cells; the scene is built once on the "
        "first process, partitioned by METIS and handed out, and the "
        "contact surfaces (small against the mesh) are gathered on every "
        "process. The results are the same to round-off.");
      prm.declare_entry(
        "Contact cell weight",
        "1",
        dealii::Patterns::Integer(1, 1000000),
        "Mesh = distributed: the weight, in METIS' partition, of a cell with "
        "a face on a contact pair's slave surface; other cells weigh 1. The "
        "process that owns a slave node evaluates its contact element, so "
        "a contact zone on one process makes the others wait: summary.txt "
        "gives the measured balance of the contact work and the weight that "
        "would even it out (1 + a slave node's contact time over a cell's "
        "assembly time). 1: every cell alike.");
      prm.declare_entry(
        "Rebalance threshold",
        "0",
        Text::non_negative_number(),
        "Mesh = distributed, several processes: at the end of a step in "
        "which the busiest process spent more than this many times the "
        "idlest one's time on contact (and the difference was more than 5 % "
        "of the step), the run writes its state (<Output/Directory>/"
        "rebalance), partitions the mesh again with every cell weighted by "
        "the measured contact work of its slave nodes, and goes on from that "
        "state; the results are the same to round-off. A rebalanced run that "
        "is still above the threshold after its next step does not "
        "rebalance again. 0: never (must be 0 or > 1).");
      prm.leave_subsection();
    }



    void
    Parallel::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Parallel");
      mesh = prm.get("Mesh") == "shared" ? Mesh::shared : Mesh::distributed;
      contact_cell_weight = prm.get_integer("Contact cell weight");
      rebalance_threshold = prm.get_double("Rebalance threshold");
      AssertThrow(rebalance_threshold == 0 || rebalance_threshold > 1,
                  dealii::ExcMessage(
                    "Parameter <Parallel/Rebalance threshold> = " +
                    prm.get("Rebalance threshold") +
                    ": a ratio of the busiest process's contact time to the "
                    "idlest one's, so 0 (never) or above 1."));
      AssertThrow(rebalance_threshold == 0 || mesh == Mesh::distributed,
                  dealii::ExcMessage(
                    "Parameter <Parallel/Rebalance threshold> = " +
                    prm.get("Rebalance threshold") +
                    " partitions a distributed mesh again; with "
                    "<Parallel/Mesh> = shared it must be 0."));
      AssertThrow(contact_cell_weight == 1 || mesh == Mesh::distributed,
                  dealii::ExcMessage(
                    "Parameter <Parallel/Contact cell weight> = " +
                    std::to_string(contact_cell_weight) +
                    " weights METIS' partition of a distributed mesh; with "
                    "<Parallel/Mesh> = shared (deal.II partitions it "
                    "itself) it must be 1."));
      prm.leave_subsection();
    }
  } // namespace Parameters
} // namespace tribos
