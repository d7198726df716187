#include <dyncontact/simulation/interruption.h>

#include <csignal>

namespace dyncontact
{
namespace
{
volatile std::sig_atomic_t received_signal = 0;

extern "C" void record_signal(const int signal)
{
  received_signal = signal;
  // A second signal ends the run at once (a step may take long, e.g. in a cascade of cuts).
  std::signal(signal, SIG_DFL);
}
} // namespace

void install_interrupt_handlers()
{
  std::signal(SIGINT, record_signal);
  std::signal(SIGTERM, record_signal);
}

int interrupt_signal()
{
  return received_signal;
}
} // namespace dyncontact
