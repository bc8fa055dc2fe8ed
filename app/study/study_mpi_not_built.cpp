// A build without MPI: a study started by mpirun is refused rather than run
// once per rank, each rank writing the same files.
#include "cli.hpp"
#include "study_runner.hpp"

namespace unfurl::app {

bool run_over_mpi(StudyRun&, int&) {
  throw UsageError("started by mpirun, but this unfurl was built without MPI (configure with UNFURL_WITH_MPI=ON)");
}

}  // namespace unfurl::app
