#include <dyncontact/interruption.h>

#include <csignal>

namespace dyncontact
{
namespace
{
volatile std::sig_atomic_t received_signal = 0;

extern "C" void record_signal(const int signal)
{
  received_signal = signal;
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
