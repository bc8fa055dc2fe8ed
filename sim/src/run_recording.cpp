#include "run_recording.hpp"

#include <algorithm>
#include <sstream>

namespace unfurl::sim {

namespace {

const char* kNotFinite = "the equations of motion have no finite value here (or the loop-closure system is singular)";

}  // namespace

RunRecording::RunRecording(Dynamics& dynamics, const RunSettings& settings, const RunObserver& observer,
                           Trajectory& trajectory, RunThreads threads)
    : own_(threads == RunThreads::two ? std::make_unique<Dynamics>(dynamics.scene()) : nullptr),
      dynamics_(own_ ? *own_ : dynamics),
      settings_(settings),
      observer_(observer),
      trajectory_(trajectory),
      monitor_(dynamics_),
      slots_(std::clamp(kStateBudget / static_cast<std::size_t>(std::max(1, dynamics.size())), kFewestSlots,
                        kMostSlots)) {}

RunRecording::~RunRecording() { close(); }

void RunRecording::close() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closing_ = true;
  }
  records_.notify_one();
  thread_.join();
}

void RunRecording::start_thread() {
  if (!own_ || threaded_) return;
  threaded_ = true;
  thread_ = std::thread([this] { run(); });
}

bool RunRecording::failed() const { return failed_.load(std::memory_order_acquire); }

RunRecording::Record& RunRecording::next_slot() {
  if (threaded_) {
    // A slot is free again once the record in it has been applied.
    std::unique_lock<std::mutex> lock(mutex_);
    producer_waiting_ = true;
    space_.wait(lock, [this] { return written_ - applied_ < slots_.size(); });
    producer_waiting_ = false;
  }
  return slots_[written_ % slots_.size()];
}

void RunRecording::push() {
  if (!threaded_) {
    apply(slots_[written_ % slots_.size()]);
    ++written_, ++applied_;
    return;
  }
  bool wake = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ++written_;
    wake = recorder_waiting_ && written_ - applied_ >= kBatch;
  }
  if (wake) records_.notify_one();
}

void RunRecording::run() {
  for (;;) {
    std::size_t begin = 0, end = 0;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      recorder_waiting_ = true;
      records_.wait(lock, [this] { return closing_ || written_ - applied_ >= kBatch; });
      recorder_waiting_ = false;
      if (applied_ == written_) return;  // closing, and nothing left
      begin = applied_, end = written_;
    }
    for (std::size_t index = begin; index < end; ++index) {
      try {
        apply(slots_[index % slots_.size()]);
      } catch (...) {
        error_ = std::current_exception();
        failed_.store(true, std::memory_order_release);
      }
      bool wake = false;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        ++applied_;
        wake = producer_waiting_;
      }
      if (wake) space_.notify_one();
    }
  }
}

std::optional<Failure> RunRecording::finish() {
  close();
  if (error_) std::rethrow_exception(error_);
  return failure_;
}

void RunRecording::fail(double t, double step, std::string check, std::string reason) {
  failure_ = Failure{t, step, std::move(check), std::move(reason)};
  failed_.store(true, std::memory_order_release);
}

void RunRecording::step_taken(double h) {
  Record& r = next_slot();
  r.kind = Kind::step_taken;
  r.step = h;
  push();
}

void RunRecording::sample(double t, const std::vector<double>& y, double dissipated, double driven, double step) {
  Record& r = next_slot();
  r.kind = Kind::sample;
  r.t = t, r.step = step, r.dissipated = dissipated, r.driven = driven;
  r.y.assign(y.begin(), y.end());
  push();
}

void RunRecording::event(const LatchEvent& e) {
  Record& r = next_slot();
  r.kind = Kind::event;
  r.event = e;
  push();
}

void RunRecording::engage(int latch) {
  Record& r = next_slot();
  r.kind = Kind::engage;
  r.event.latch = latch;
  push();
}

void RunRecording::restarted() {
  next_slot().kind = Kind::restarted;
  push();
}

void RunRecording::latched() {
  next_slot().kind = Kind::latched;
  push();
}

void RunRecording::step_end(double t, const std::vector<double>& y, double step) {
  Record& r = next_slot();
  r.kind = Kind::step_end;
  r.t = t, r.step = step;
  r.y.assign(y.begin(), y.end());
  push();
}

void RunRecording::apply(const Record& r) {
  if (failed()) return;  // the run ended there
  switch (r.kind) {
    case Kind::step_taken:
      monitor_.step_taken(r.step);
      return;
    case Kind::restarted:
      monitor_.restarted();
      return;
    case Kind::latched:
      monitor_.latched();
      return;
    case Kind::engage:
      // The integrator's Dynamics engaged it at the same point of the run.
      if (own_) own_->latch_state().engage(r.event.latch);
      return;
    case Kind::event:
      trajectory_.events.push_back(r.event);
      if (observer_.on_event) observer_.on_event(r.event);
      return;
    case Kind::sample: {
      if (!dynamics_.observe(r.t, r.y.data(), observation_)) return fail(r.t, r.step, "evaluation", kNotFinite);
      observation_.energy.dissipated = r.dissipated;
      observation_.energy.driven = r.driven;
      Sample s;
      s.t = r.t;
      s.y = r.y;
      s.q_dot = observation_.q_dot;
      s.closure = observation_.closure;
      s.energy = observation_.energy;
      s.momentum = observation_.momentum;
      s.loads = observation_.loads;
      trajectory_.samples.push_back(std::move(s));
      if (observer_.on_sample) observer_.on_sample(trajectory_.samples.back());
      return;
    }
    case Kind::step_end: {
      // The loads and the gap at every step's end, the start included.
      const std::optional<double> gap = monitor_.observe(r.t, r.y.data());
      if (!gap) return fail(r.t, r.step, "evaluation", kNotFinite);
      if (*gap <= settings_.max_closure) return;
      std::ostringstream why;
      why << "a loop opened by " << *gap << " (rad, or length over the mechanism's " << dynamics_.scales().length
          << " m; limit " << settings_.max_closure << "): the regulator lost the loop";
      return fail(r.t, r.step, "closure", why.str());
    }
  }
}

}  // namespace unfurl::sim
