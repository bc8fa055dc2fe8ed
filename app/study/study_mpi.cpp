// The study over MPI ranks. Rank 0 works like any rank (on its own threads)
// and, on its main thread, answers the others: a rank sends the record of
// the case it finished (an empty one at first) and gets the next case's
// index back, -1 when none is left. Rank 0 polls instead of blocking in a
// receive: Open MPI's blocking receive spins, and would take a core from
// the cases on a small machine.
#include <mpi.h>

#include <chrono>
#include <string>
#include <thread>

#include "study_runner.hpp"

namespace unfurl::app {

namespace {

constexpr int kRecordTag = 1, kCaseTag = 2;
const char kCancelled = '\x18';

class MpiSession {
 public:
  MpiSession() {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiSession() { MPI_Finalize(); }
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0, size_ = 1;
};

void send_text(const std::string& text, int to, int tag) {
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

void work_for_rank_zero(StudyRun& run) {
  send_text("", 0, kRecordTag);
  for (;;) {
    long index = -1;
    MPI_Recv(&index, 1, MPI_LONG, 0, kCaseTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (index < 0) return;
    const auto i = static_cast<std::size_t>(index);
    const std::optional<std::string> record = run.run_case(i);
    send_text(std::to_string(i) + "\n" + (record ? *record : std::string(1, kCancelled)), 0, kRecordTag);
    if (!record) return;
  }
}

// Rank 0's main thread: hands out cases until every other rank has been
// told to stop (or has stopped on a signal).
void dispatch(StudyRun& run, std::atomic<std::size_t>& next, int ranks) {
  int stopped = 0;
  std::string buffer;
  while (stopped < ranks - 1) {
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kRecordTag, MPI_COMM_WORLD, &arrived, &status);
    if (!arrived) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      continue;
    }
    int count = 0;
    MPI_Get_count(&status, MPI_CHAR, &count);
    buffer.resize(static_cast<std::size_t>(count));
    MPI_Recv(buffer.data(), count, MPI_CHAR, status.MPI_SOURCE, kRecordTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (!buffer.empty()) {
      const auto newline = buffer.find('\n');
      const std::size_t i = std::stoul(buffer.substr(0, newline));
      const std::string record = buffer.substr(newline + 1);
      if (record.size() == 1 && record[0] == kCancelled) {
        ++stopped;
        continue;
      }
      run.record(i, record);
    }
    const std::size_t k = run.cancel() ? run.pending().size() : next++;
    const long index = k < run.pending().size() ? static_cast<long>(run.pending()[k]) : -1;
    MPI_Send(&index, 1, MPI_LONG, status.MPI_SOURCE, kCaseTag, MPI_COMM_WORLD);
    if (index < 0) ++stopped;
  }
}

}  // namespace

bool run_over_mpi(StudyRun& run, int& processes) {
  const MpiSession mpi;
  processes = mpi.size();
  if (mpi.rank() != 0) {
    work_for_rank_zero(run);
    return false;
  }
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::thread local([&] {
    try {
      run_on_threads(run, next, run.options().jobs);
    } catch (...) {
      error = std::current_exception();
    }
  });
  dispatch(run, next, mpi.size());
  local.join();
  if (error) std::rethrow_exception(error);
  return true;
}

}  // namespace unfurl::app
