#include "fpmshell/driver/interrupt_guard.hpp"

namespace fpmshell {
namespace {

volatile std::sig_atomic_t g_received = 0;  // written by the handler only (async-signal-safe)

extern "C" void on_interrupt(int signal_number) { g_received = signal_number; }

}  // namespace

InterruptGuard::InterruptGuard() {
    g_received = 0;
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND | SA_RESTART;  // a second signal: the default action, at once
    sigaction(SIGINT, &action, &old_int_);
    sigaction(SIGTERM, &action, &old_term_);
}

InterruptGuard::~InterruptGuard() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
}

int InterruptGuard::received() { return static_cast<int>(g_received); }

const char* signal_name(int signal_number) {
    switch (signal_number) {
        case SIGINT:
            return "SIGINT";
        case SIGTERM:
            return "SIGTERM";
        default:
            return "a signal";
    }
}

}  // namespace fpmshell
