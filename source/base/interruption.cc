#include <tribos/base/interruption.h>

#include <csignal>

namespace tribos
{
  namespace
  {
    volatile std::sig_atomic_t pending_signal = 0;

    extern "C" void
    note_signal(const int signal_number)
    {
      pending_signal = signal_number;
      // A second signal of the kind takes the default action.
      std::signal(signal_number, SIG_DFL);
    }
  } // namespace



  Interrupted::Interrupted(const int signal_number, const bool in_setup)
    : std::runtime_error("interrupted by " + name(signal_number) +
                         (in_setup ? " during the setup" : ""))
    , number(signal_number)
    , setup(in_setup)
  {
  }



  std::string
  Interrupted::name(const int signal_number)
  {
    switch (signal_number)
    {
      case SIGTERM:
        return "SIGTERM";
      case SIGINT:
        return "SIGINT";
      default:
        return "signal " + std::to_string(signal_number);
    }
  }



  namespace Interruption
  {
    void
    install()
    {
      std::signal(SIGTERM, note_signal);
      std::signal(SIGINT, note_signal);
      // A closed pipe on the console (tribos ... | head -2) is no reason to
      // stop a run: the console's writes fail quietly and the run ends
      // with its files and summary as usual.
      std::signal(SIGPIPE, SIG_IGN);
    }



    void
    check(const MPI_Comm communicator, const bool in_setup)
    {
      int here = pending_signal, any = 0;
      MPI_Allreduce(&here, &any, 1, MPI_INT, MPI_MAX, communicator);
      if (any != 0)
        throw Interrupted(any, in_setup);
    }
  } // namespace Interruption
} // namespace tribos
