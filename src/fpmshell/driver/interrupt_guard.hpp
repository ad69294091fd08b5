// Ctrl-C (SIGINT) and SIGTERM during a dynamic run: the run ends after the step it is in,
// writing a restart file and every result so far, like LS-DYNA's sense switch "sw1" (a batch
// system's SIGTERM at the end of a job's time slot loses nothing either). A second signal
// ends the process at once (the handler is reset after the first).
#pragma once

#include <csignal>

namespace fpmshell {

/// Catches SIGINT and SIGTERM while it lives; restores the handlers before it.
class InterruptGuard {
public:
    InterruptGuard();
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    /// The signal received since construction (SIGINT or SIGTERM), 0 if none.
    [[nodiscard]] static int received();

private:
    struct sigaction old_int_ {};
    struct sigaction old_term_ {};
};

/// "SIGINT", "SIGTERM" or "a signal".
[[nodiscard]] const char* signal_name(int signal_number);

}  // namespace fpmshell
