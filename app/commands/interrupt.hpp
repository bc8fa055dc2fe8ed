// SIGINT and SIGTERM end a long run cleanly: while an InterruptScope is
// alive they set a flag the run polls after every step (RunObserver::cancel)
// instead of killing the process, so the results so far are written
// complete. A second signal of the same kind kills as usual.
#pragma once

#include <atomic>

namespace unfurl::app {

class InterruptScope {
 public:
  InterruptScope();
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

  const std::atomic<bool>& flag() const;
  // The signal that arrived (SIGINT, SIGTERM), 0 if none.
  int signal() const;
  // "SIGINT" or "SIGTERM".
  const char* signal_name() const;
  // The exit status of a process ended by the signal: 128 + its number.
  int exit_status() const { return 128 + signal(); }
};

}  // namespace unfurl::app
