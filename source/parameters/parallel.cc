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
      prm.leave_subsection();
    }



    void
    Parallel::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Parallel");
      mesh = prm.get("Mesh") == "shared" ? Mesh::shared : Mesh::distributed;
      contact_cell_weight = prm.get_integer("Contact cell weight");
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
