#include "interrupt.hpp"

#include <csignal>

namespace unfurl::app {

namespace {

std::atomic<bool> interrupted{false};
volatile std::sig_atomic_t received = 0;
struct sigaction previous_int, previous_term;

void on_signal(int number) {
  received = number;
  interrupted.store(true);
  // The next one of the same kind gets the default action: a run that does
  // not stop can still be killed by pressing Ctrl+C twice.
  std::signal(number, SIG_DFL);
}

}  // namespace

static_assert(std::atomic<bool>::is_always_lock_free, "the flag is set in a signal handler");

InterruptScope::InterruptScope() {
  interrupted.store(false);
  received = 0;
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &previous_int);
  sigaction(SIGTERM, &action, &previous_term);
}

InterruptScope::~InterruptScope() {
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
}

const std::atomic<bool>& InterruptScope::flag() const { return interrupted; }

int InterruptScope::signal() const { return received; }

const char* InterruptScope::signal_name() const {
  return received == SIGTERM ? "SIGTERM" : received == SIGINT ? "SIGINT" : "a signal";
}

}  // namespace unfurl::app
