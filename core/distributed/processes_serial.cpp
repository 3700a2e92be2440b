// One process: the build without MPI (processes.hpp).
#include "core/distributed/processes.hpp"

namespace revsph::distributed {

ProcessSession::ProcessSession(int&, char**&) {}
ProcessSession::~ProcessSession() = default;

int process_rank() {
  return 0;
}
int process_count() {
  return 1;
}

fixedpoint::int128 sum_over_processes(fixedpoint::int128 local) {
  return local;
}
std::int64_t sum_over_processes(std::int64_t local) {
  return local;
}
fixedpoint::ExactDoubleSum sum_over_processes(const fixedpoint::ExactDoubleSum& local) {
  return local;
}
double max_over_processes(double local) {
  return local;
}
double min_over_processes(double local) {
  return local;
}

} // namespace revsph::distributed
