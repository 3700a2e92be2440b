#pragma once
// The processes of a run and the reductions across them that cannot depend on how the particles
// are split among them (docs/design/distributed.md, piece 2): sums of integers (exact in any
// order), exact sums of doubles (fixedpoint/exact_double_sum.hpp), maxima and minima. There is no
// floating-point sum: its total would depend on the order in which the processes' parts are
// added.
//
// Built with -DREVSPH_MPI=ON these are MPI_COMM_WORLD's processes (processes_mpi.cpp); without
// it, one process (processes_serial.cpp), and every reduction returns its argument.

#include "fixedpoint/exact_double_sum.hpp"
#include "fixedpoint/exact_sum.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace revsph::distributed {

// Starts the processes' communication for the life of this object (MPI_Init_thread with
// threads funnelled through the main thread, MPI_Finalize at the end): one in main, before
// anything else reduces.
class ProcessSession {
public:
  ProcessSession(int& argc, char**& argv);
  ~ProcessSession();
  ProcessSession(const ProcessSession&) = delete;
  ProcessSession& operator=(const ProcessSession&) = delete;
};

// This process's rank in [0, process_count()).
int process_rank();
int process_count();

// Over every process.
fixedpoint::int128 sum_over_processes(fixedpoint::int128 local);
std::int64_t sum_over_processes(std::int64_t local);
fixedpoint::ExactDoubleSum sum_over_processes(const fixedpoint::ExactDoubleSum& local);
double max_over_processes(double local);
// Personalised all-to-all: `send` holds the bytes for process 0, then for process 1, ...,
// `send_bytes[p]` of them for process p (one entry per process). Returns what every process sent
// to this one, in rank order, and the byte count from each in `received_bytes`.
std::vector<std::byte> exchange_bytes(std::span<const std::byte> send,
                                      std::span<const std::size_t> send_bytes,
                                      std::vector<std::size_t>& received_bytes);
// The same when this process knows how many bytes each process sends it (`receive_bytes`, one
// entry per process: a ghost plan's fixed lists), which saves the exchange of the counts.
std::vector<std::byte> exchange_bytes(std::span<const std::byte> send,
                                      std::span<const std::size_t> send_bytes,
                                      std::span<const std::size_t> receive_bytes);
// Bitwise or over every process (flags: which fields changed somewhere).
std::uint64_t or_over_processes(std::uint64_t local);
double min_over_processes(double local);

// Ends every process at once with `status` (MPI_Abort; std::exit with one process): what a
// process that met an error the others cannot know of (a fault in its own particles) does, so
// that none waits for it in an exchange. The launcher reports the status.
[[noreturn]] void end_every_process(int status);

} // namespace revsph::distributed
