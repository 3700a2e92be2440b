// index_order_stream.hpp over MPI_COMM_WORLD: each chunk is gathered on process 0 from the
// processes' index ranges, with the indices, and put in order there.
#include "core/distributed/index_order_stream.hpp"

#include "core/distributed/communication_tally.hpp"
#include "core/distributed/processes.hpp"

#include <mpi.h>

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <vector>

namespace revsph::distributed {

void stream_in_index_order(std::span<const std::uint64_t> indices,
                           std::span<const std::int64_t> values, std::uint64_t total,
                           std::size_t chunk,
                           const std::function<void(std::span<const std::int64_t>)>& consumer) {
  if (indices.size() != values.size() || !std::is_sorted(indices.begin(), indices.end())) {
    throw std::invalid_argument("stream_in_index_order: indices unsorted or values missing");
  }
  const bool first = process_rank() == 0;
  const auto processes = static_cast<std::size_t>(process_count());
  std::vector<int> counts(processes), offsets(processes);
  std::vector<std::uint64_t> gathered_indices;
  std::vector<std::int64_t> gathered_values, ordered;
  std::vector<unsigned char> seen;
  std::size_t from = 0;
  for (std::uint64_t low = 0; low < total; low += chunk) {
    const std::uint64_t high = std::min<std::uint64_t>(total, low + chunk);
    const auto to = static_cast<std::size_t>(
        std::lower_bound(indices.begin() + static_cast<std::ptrdiff_t>(from), indices.end(), high) -
        indices.begin());
    const int mine = static_cast<int>(to - from);
    std::optional<CommunicationTimer> timer(std::in_place,
                                            first ? 0 : 16 * static_cast<std::uint64_t>(mine));
    MPI_Gather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    int sum = 0;
    for (std::size_t p = 0; p < processes; ++p) {
      offsets[p] = sum;
      sum += counts[p];
    }
    if (first) {
      gathered_indices.resize(static_cast<std::size_t>(sum));
      gathered_values.resize(static_cast<std::size_t>(sum));
    }
    MPI_Gatherv(indices.data() + from, mine, MPI_UINT64_T, gathered_indices.data(), counts.data(),
                offsets.data(), MPI_UINT64_T, 0, MPI_COMM_WORLD);
    MPI_Gatherv(values.data() + from, mine, MPI_INT64_T, gathered_values.data(), counts.data(),
                offsets.data(), MPI_INT64_T, 0, MPI_COMM_WORLD);
    timer.reset();
    from = to;
    int complete = 1;
    if (first) {
      const std::size_t size = high - low;
      ordered.assign(size, 0);
      seen.assign(size, 0);
      complete = static_cast<std::size_t>(sum) == size ? 1 : 0;
      for (std::size_t n = 0; complete != 0 && n < gathered_indices.size(); ++n) {
        const std::uint64_t index = gathered_indices[n];
        if (index < low || index >= high || seen[index - low] != 0) {
          complete = 0;
          break;
        }
        seen[index - low] = 1;
        ordered[index - low] = gathered_values[n];
      }
    }
    {
      const CommunicationTimer verdict_timer(sizeof complete);
      MPI_Bcast(&complete, 1, MPI_INT, 0, MPI_COMM_WORLD);
    }
    if (complete == 0) {
      throw std::invalid_argument("stream_in_index_order: the particles do not cover the run");
    }
    if (first) {
      consumer(ordered);
    }
  }
  if (sum_over_processes(static_cast<std::int64_t>(indices.size() - from)) != 0) {
    throw std::invalid_argument("stream_in_index_order: an index beyond the run's particles");
  }
}

std::string broadcast_from_first(const std::string& text) {
  auto size = static_cast<std::uint64_t>(text.size());
  const CommunicationTimer timer(text.size());
  MPI_Bcast(&size, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  std::string result = text;
  result.resize(size);
  MPI_Bcast(result.data(), static_cast<int>(size), MPI_CHAR, 0, MPI_COMM_WORLD);
  return result;
}

} // namespace revsph::distributed
