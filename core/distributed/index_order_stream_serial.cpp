// One process holds every particle in index order (index_order_stream.hpp without MPI).
#include "core/distributed/index_order_stream.hpp"

#include <stdexcept>

namespace revsph::distributed {

void stream_in_index_order(std::span<const std::uint64_t> indices,
                           std::span<const std::int64_t> values, std::uint64_t total,
                           std::size_t chunk,
                           const std::function<void(std::span<const std::int64_t>)>& consumer) {
  if (indices.size() != total || values.size() != total) {
    throw std::invalid_argument("stream_in_index_order: the particles do not cover the run");
  }
  for (std::uint64_t i = 0; i < total; ++i) {
    if (indices[i] != i) {
      throw std::invalid_argument("stream_in_index_order: indices out of order");
    }
  }
  for (std::size_t first = 0; first < values.size(); first += chunk) {
    consumer(values.subspan(first, std::min(chunk, values.size() - first)));
  }
}

std::string broadcast_from_first(const std::string& text) {
  return text;
}

} // namespace revsph::distributed
