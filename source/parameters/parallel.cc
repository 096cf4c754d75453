#include <tribos/parameters/parallel.h>

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
      prm.leave_subsection();
    }



    void
    Parallel::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Parallel");
      mesh = prm.get("Mesh") == "shared" ? Mesh::shared : Mesh::distributed;
      prm.leave_subsection();
    }
  } // namespace Parameters
} // namespace tribos
