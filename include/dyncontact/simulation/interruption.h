#pragma once

#include <dyncontact/base/global.h>

#include <stdexcept>
#include <string>

namespace dyncontact
{
/**
 * SIGINT and SIGTERM as a request to stop cleanly: the handlers only record the signal; the time
 * loop asks after each accepted step (interrupt_signal(), agreed over all MPI ranks there), writes
 * a checkpoint and throws RunInterrupted; a second signal of the same kind ends the process at
 * once. It does not write anything itself.
 */
void install_interrupt_handlers();

/** The signal received since install_interrupt_handlers(), or 0. */
int interrupt_signal();

/**
 * A run stopped on request after writing a checkpoint; the message says how to resume. main exits
 * with 128 + signal, the shell's convention for a process ended by that signal.
 */
class RunInterrupted : public std::runtime_error
{
public:
  /** `directory` holds the checkpoint (and the run's results). */
  RunInterrupted(const std::string& message, int signal, const std::string& directory)
      : std::runtime_error(message), signal_number(signal), checkpoint_directory(directory)
  {
  }
  int signal() const { return signal_number; }
  const std::string& directory() const { return checkpoint_directory; }

private:
  int signal_number;
  std::string checkpoint_directory;
};
} // namespace dyncontact
