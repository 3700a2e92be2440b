// One process: the build without MPI (processes.hpp).
#include "core/distributed/processes.hpp"

#include <cstdlib>

namespace revsph::distributed {

ProcessSession::ProcessSession(int&, char**&) {}
ProcessSession::~ProcessSession() = default;

void end_every_process(int status) {
  std::exit(status);
}

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
std::vector<std::byte> exchange_bytes(std::span<const std::byte> send,
                                      std::span<const std::size_t> send_bytes,
                                      std::vector<std::size_t>& received_bytes) {
  received_bytes.assign(1, send_bytes.empty() ? 0 : send_bytes[0]);
  return {send.begin(), send.begin() + static_cast<std::ptrdiff_t>(received_bytes[0])};
}
std::vector<std::byte> exchange_bytes(std::span<const std::byte> send,
                                      std::span<const std::size_t> send_bytes,
                                      std::span<const std::size_t>) {
  std::vector<std::size_t> received_bytes;
  return exchange_bytes(send, send_bytes, received_bytes);
}
std::uint64_t or_over_processes(std::uint64_t local) {
  return local;
}
double max_over_processes(double local) {
  return local;
}
double min_over_processes(double local) {
  return local;
}

} // namespace revsph::distributed
