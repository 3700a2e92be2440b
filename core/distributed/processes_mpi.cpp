// MPI_COMM_WORLD's processes (processes.hpp), built with -DREVSPH_MPI=ON.
#include "core/distributed/processes.hpp"

#include "core/distributed/communication_tally.hpp"

#include <cstdlib>

#include <mpi.h>

#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace revsph::distributed {

namespace {

__extension__ using uint128 = unsigned __int128;

// A 128-bit integer travels as 16 bytes; the reduction adds them as integers (modulo 2^128, as
// the accumulators do: the total is exact and independent of the order of the processes).
MPI_Datatype int128_type = MPI_DATATYPE_NULL;
MPI_Op int128_sum = MPI_OP_NULL;

void add_int128(void* in, void* inout, int* count, MPI_Datatype*) {
  for (int i = 0; i < *count; ++i) {
    fixedpoint::int128 a = 0;
    fixedpoint::int128 b = 0;
    std::memcpy(&a, static_cast<char*>(in) + 16 * i, 16);
    std::memcpy(&b, static_cast<char*>(inout) + 16 * i, 16);
    const auto total =
        static_cast<fixedpoint::int128>(static_cast<uint128>(a) + static_cast<uint128>(b));
    std::memcpy(static_cast<char*>(inout) + 16 * i, &total, 16);
  }
}

// Bytes a reduction hands to the other processes (none when there are none).
std::uint64_t to_others(std::size_t bytes) {
  int count = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &count);
  return count > 1 ? bytes : 0;
}

void check(int status, const char* what) {
  if (status != MPI_SUCCESS) {
    throw std::runtime_error(std::string("MPI: ") + what + " failed");
  }
}

// One value reduced over every process with `op`, timed.
template <class T>
T all_reduce(T local, MPI_Datatype type, MPI_Op op, const char* what) {
  T result{};
  const CommunicationTimer timer(to_others(sizeof local));
  check(MPI_Allreduce(&local, &result, 1, type, op, MPI_COMM_WORLD), what);
  return result;
}

} // namespace

ProcessSession::ProcessSession(int& argc, char**& argv) {
  int provided = 0;
  check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  check(MPI_Type_contiguous(16, MPI_BYTE, &int128_type), "MPI_Type_contiguous");
  check(MPI_Type_commit(&int128_type), "MPI_Type_commit");
  check(MPI_Op_create(&add_int128, /*commute=*/1, &int128_sum), "MPI_Op_create");
}

ProcessSession::~ProcessSession() {
  MPI_Op_free(&int128_sum);
  MPI_Type_free(&int128_type);
  MPI_Finalize();
}

void end_every_process(int status) {
  MPI_Abort(MPI_COMM_WORLD, status);
  std::exit(status); // MPI_Abort does not return; for the compiler
}

int process_rank() {
  int rank = 0;
  check(MPI_Comm_rank(MPI_COMM_WORLD, &rank), "MPI_Comm_rank");
  return rank;
}

int process_count() {
  int count = 1;
  check(MPI_Comm_size(MPI_COMM_WORLD, &count), "MPI_Comm_size");
  return count;
}

fixedpoint::int128 sum_over_processes(fixedpoint::int128 local) {
  return all_reduce(local, int128_type, int128_sum, "MPI_Allreduce (int128 sum)");
}

std::int64_t sum_over_processes(std::int64_t local) {
  return all_reduce(local, MPI_INT64_T, MPI_SUM, "MPI_Allreduce (int64 sum)");
}

fixedpoint::ExactDoubleSum sum_over_processes(const fixedpoint::ExactDoubleSum& local) {
  // Every process gathers every part and adds them: exact, so the order does not matter, and
  // 282 bytes a process is less than a custom reduction's bookkeeping.
  using Image = fixedpoint::ExactDoubleSum::Image;
  const Image mine = local.image();
  std::vector<Image> parts(static_cast<std::size_t>(process_count()));
  const CommunicationTimer timer(to_others(mine.size()));
  check(MPI_Allgather(mine.data(), static_cast<int>(mine.size()), MPI_BYTE, parts.data(),
                      static_cast<int>(mine.size()), MPI_BYTE, MPI_COMM_WORLD),
        "MPI_Allgather (exact sum of doubles)");
  fixedpoint::ExactDoubleSum total;
  for (const Image& part : parts) {
    total.add(fixedpoint::ExactDoubleSum::from_image(part));
  }
  return total;
}

namespace {

// MPI's counts and offsets (int: a part above 2 GiB is refused rather than cut).
void to_counts(std::span<const std::size_t> bytes, std::vector<int>& counts,
               std::vector<int>& offsets) {
  counts.resize(bytes.size());
  offsets.resize(bytes.size());
  std::size_t offset = 0;
  for (std::size_t p = 0; p < bytes.size(); ++p) {
    if (bytes[p] > static_cast<std::size_t>(std::numeric_limits<int>::max()) ||
        offset > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
      throw std::runtime_error("MPI: a message of more than 2 GiB");
    }
    counts[p] = static_cast<int>(bytes[p]);
    offsets[p] = static_cast<int>(offset);
    offset += bytes[p];
  }
}

std::vector<std::byte> all_to_all(std::span<const std::byte> send,
                                  std::span<const std::size_t> send_bytes,
                                  std::span<const std::size_t> receive_bytes) {
  std::vector<int> send_counts, send_offsets, receive_counts, receive_offsets;
  to_counts(send_bytes, send_counts, send_offsets);
  to_counts(receive_bytes, receive_counts, receive_offsets);
  std::size_t total = 0;
  for (const std::size_t bytes : receive_bytes) {
    total += bytes;
  }
  std::vector<std::byte> received(total);
  const CommunicationTimer timer(send.size() -
                                 send_bytes[static_cast<std::size_t>(process_rank())]);
  ++communication_tally().exchanges;
  check(MPI_Alltoallv(send.data(), send_counts.data(), send_offsets.data(), MPI_BYTE,
                      received.data(), receive_counts.data(), receive_offsets.data(), MPI_BYTE,
                      MPI_COMM_WORLD),
        "MPI_Alltoallv");
  return received;
}

} // namespace

std::vector<std::byte> exchange_bytes(std::span<const std::byte> send,
                                      std::span<const std::size_t> send_bytes,
                                      std::vector<std::size_t>& received_bytes) {
  const auto count = static_cast<std::size_t>(process_count());
  std::vector<int> send_counts, send_offsets;
  to_counts(send_bytes, send_counts, send_offsets);
  std::vector<int> receive_counts(count);
  {
    const CommunicationTimer timer(sizeof(int) * (count - 1));
    check(MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT,
                       MPI_COMM_WORLD),
          "MPI_Alltoall (byte counts)");
  }
  received_bytes.assign(receive_counts.begin(), receive_counts.end());
  return all_to_all(send, send_bytes, received_bytes);
}

std::vector<std::byte> exchange_bytes(std::span<const std::byte> send,
                                      std::span<const std::size_t> send_bytes,
                                      std::span<const std::size_t> receive_bytes) {
  return all_to_all(send, send_bytes, receive_bytes);
}

std::uint64_t or_over_processes(std::uint64_t local) {
  return all_reduce(local, MPI_UINT64_T, MPI_BOR, "MPI_Allreduce (or)");
}

double max_over_processes(double local) {
  return all_reduce(local, MPI_DOUBLE, MPI_MAX, "MPI_Allreduce (max)");
}

double min_over_processes(double local) {
  return all_reduce(local, MPI_DOUBLE, MPI_MIN, "MPI_Allreduce (min)");
}

} // namespace revsph::distributed
