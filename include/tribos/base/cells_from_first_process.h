#ifndef tribos_base_cells_from_first_process_h
#define tribos_base_cells_from_first_process_h

#include <deal.II/base/mpi.h>
#include <deal.II/grid/cell_id.h>
#include <deal.II/grid/tria.h>

#include <map>
#include <vector>

namespace tribos
{
  /**
   * Numbers about cells that only the first process knows, handed to the
   * processes that hold those cells: the distributed mesh is built from a
   * serial mesh on the first process (the scene's), which keeps what a
   * description does not carry, such as the vertices of cells refined at
   * a contact point or a second-order mesh's support points. Every process
   * names its cells by CellId (@p mine, the same in both meshes); the first
   * process appends, for each, what @p answer writes for that cell of
   * @p serial; each process receives its cells' numbers in the order of
   * @p mine. Collective.
   */
  template <int dim, typename Answer>
  std::vector<double>
  cells_from_first_process(const MPI_Comm                     communicator,
                           const dealii::Triangulation<dim>  &serial,
                           const std::vector<dealii::CellId> &mine,
                           const Answer                      &answer)
  {
    std::vector<dealii::CellId::binary_type> ids;
    for (const auto &id : mine)
      ids.push_back(id.template to_binary<dim>());
    const auto requests = dealii::Utilities::MPI::gather(communicator, ids, 0);
    std::map<unsigned int, std::vector<double>> answers;
    for (unsigned int rank = 0; rank < requests.size(); ++rank)
      for (const auto &id : requests[rank])
        answer(serial.create_cell_iterator(dealii::CellId(id)), answers[rank]);
    const auto received =
      dealii::Utilities::MPI::some_to_some(communicator, answers);
    const auto from_first = received.find(0);
    return from_first == received.end() ? std::vector<double>() :
                                          from_first->second;
  }
} // namespace tribos

#endif
