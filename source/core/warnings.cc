#include <tribos/core/warnings.h>

#include <deal.II/base/utilities.h>

#include <iostream>

namespace tribos
{
  Warnings::Warnings(const MPI_Comm communicator)
    : communicator(communicator)
  {
  }



  void
  Warnings::warn(const std::string &message)
  {
    messages.push_back(message);
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      std::cerr << "tribos: WARNING: " << message << std::endl;
  }



  const std::vector<std::string> &
  Warnings::list() const
  {
    return messages;
  }
} // namespace tribos
