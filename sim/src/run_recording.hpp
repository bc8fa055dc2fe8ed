// What a run does at each step's end and each sample besides integrating:
// the loads, their peaks and the gap check at every step's end (RunMonitor),
// and the samples' records (trajectory, loads, energy). On the pantograph
// that is 40 % of a run's time (the integrator's thread takes 118 ms of the
// 199 that one thread takes), and none of it feeds the integrator back: it reads states, it does not
// change them. So on two cores it runs on a thread of its own beside the
// integrator's, on a Dynamics of its own, fed the integrator's states in
// the order the run made them; the results are the same bytes as on one
// thread (every evaluation is a function of its state alone, and the state
// the monitor remembers, where the motion passed a branch point, follows the
// same sequence of step ends).
//
// A check that fails there (a loop opened, a state with no finite value)
// ends the run at the step it failed on, as on one thread: the records the
// integrator made after it are dropped, and the integrator stops at its
// next step (its counts of steps and evaluations include those it took past
// the failure).
#pragma once

#include <atomic>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "run_monitor.hpp"
#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/simulation.hpp"

namespace unfurl::sim {

class RunRecording {
 public:
  // dynamics: the integrator's, which records with it on one thread.
  RunRecording(Dynamics& dynamics, const RunSettings& settings, const RunObserver& observer, Trajectory& trajectory,
               RunThreads threads);
  ~RunRecording();
  RunRecording(const RunRecording&) = delete;
  RunRecording& operator=(const RunRecording&) = delete;

  // From here on the records go to the recording's thread (with two).
  void start_thread();

  // The records, in the order the run makes them. step: the integrator's
  // current step size, which a failure reports.
  void step_taken(double h);
  void sample(double t, const std::vector<double>& y, double dissipated, double driven, double step);
  void event(const LatchEvent& e);
  void engage(int latch);
  void restarted();
  void latched();
  void step_end(double t, const std::vector<double>& y, double step);

  // Whether a check has failed on a record made so far (on two threads it
  // may lag a few steps behind the integrator).
  bool failed() const;
  // Waits for every record made; then the first check that failed.
  std::optional<Failure> finish();
  // What the monitor found (after finish()).
  const RunMonitor& monitor() const { return monitor_; }

 private:
  enum class Kind { step_taken, sample, event, engage, restarted, latched, step_end };
  struct Record {
    Kind kind = Kind::step_taken;
    double t = 0, step = 0, dissipated = 0, driven = 0;
    LatchEvent event;
    std::vector<double> y;
  };

  Record& next_slot();  // the slot the next record is written into
  void push();          // hands it over (or applies it, on one thread)
  void apply(const Record& r);
  void fail(double t, double step, std::string check, std::string reason);
  void run();    // the recording's thread
  void close();  // lets it apply what is left, and joins it

  // The records wait in slots, as many as hold kStateBudget numbers of state
  // (16 MB) within [kFewestSlots, kMostSlots]: enough for the recording to
  // fall behind where its work is heavier (after a latch-up, where the loads
  // decompose W at every step) and catch up elsewhere; with 64 the
  // pantograph's integrator waited for it 15 % of its run. Its thread is
  // woken for kBatch records at a time, not for each: a wake-up costs the
  // integrator's thread a system call, as much as a record's work on small
  // scenes.
  static constexpr std::size_t kStateBudget = std::size_t{1} << 21, kFewestSlots = 64, kMostSlots = 4096;
  static constexpr std::size_t kBatch = 16;

  std::unique_ptr<Dynamics> own_;  // with two threads
  Dynamics& dynamics_;
  const RunSettings& settings_;
  const RunObserver& observer_;
  Trajectory& trajectory_;
  RunMonitor monitor_;
  Observation observation_;
  std::optional<Failure> failure_;

  std::vector<Record> slots_;              // a ring
  std::size_t written_ = 0, applied_ = 0;  // records handed over and applied
  bool threaded_ = false, closing_ = false, recorder_waiting_ = false, producer_waiting_ = false;
  std::atomic<bool> failed_{false};  // failure_ or error_ is set
  std::mutex mutex_;
  std::condition_variable space_, records_;
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace unfurl::sim
