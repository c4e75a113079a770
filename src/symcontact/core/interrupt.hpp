#pragma once
/// \file interrupt.hpp
/// SIGINT and SIGTERM as a request to stop: the handler only records the signal (the one thing a
/// signal handler may safely do, POSIX async-signal-safety), and long computations poll
/// interrupt_signal() where stopping is cheap and leaves consistent state: between load steps, and at
/// each IPOPT iteration (its intermediate callback). The program then finishes the file it is writing,
/// records the interruption and exits with 128 + the signal number (130 for SIGINT, 143 for SIGTERM).
///
/// The flag is process-wide state, set only by the handler and read everywhere else.

namespace symcontact {

/// Installs the handlers for SIGINT and SIGTERM (sigaction, SA_RESTART so that interrupted reads and
/// writes resume). Call once, from main().
void install_interrupt_handlers();

/// The signal number received (SIGINT or SIGTERM), or 0 when none has been.
int interrupt_signal();

/// True once a handled signal has arrived.
inline bool interrupt_requested() { return interrupt_signal() != 0; }

}  // namespace symcontact
