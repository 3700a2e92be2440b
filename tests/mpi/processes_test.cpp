// The reductions across processes (core/distributed/processes.hpp) give every process the same
// total as one process adding every term: the exact integer sum of 100 000 fixed-point terms
// split round-robin among the processes, the exact sum of the doubles themselves (the same bits as
// one process adding them in index order into one accumulator), and their maximum and minimum. CTest runs
// this program on 1, 2 and 3 processes (tests/mpi/CMakeLists.txt); built without MPI it is the
// one-process case.

#include "core/distributed/processes.hpp"
#include "fixedpoint/conversion.hpp"
#include "fixedpoint/scale.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <span>
#include <vector>

namespace {

using revsph::distributed::process_count;
using revsph::distributed::process_rank;

std::vector<double> terms() {
  std::mt19937_64 generator(12345);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<double> values(100000);
  for (std::size_t i = 0; i < values.size(); ++i) {
    // Spread over 30 binary orders of magnitude, as per-particle energies are.
    values[i] = uniform(generator) * std::ldexp(1.0, static_cast<int>(i % 30) - 15);
  }
  return values;
}

TEST(Processes, ExactSumIsTheOneProcessSumForAnySplit) {
  const revsph::fixedpoint::Scale scale = revsph::fixedpoint::Scale::covering(1e5 * 32768.0, 62);
  revsph::fixedpoint::int128 everything = 0;
  revsph::fixedpoint::int128 mine = 0;
  std::int64_t my_count = 0;
  const std::vector<double> values = terms();
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::int64_t raw = 0;
    ASSERT_TRUE(revsph::fixedpoint::try_to_fixed(values[i], scale, raw));
    everything += raw;
    if (static_cast<int>(i % static_cast<std::size_t>(process_count())) == process_rank()) {
      mine += raw;
      ++my_count;
    }
  }
  EXPECT_TRUE(revsph::distributed::sum_over_processes(mine) == everything);
  EXPECT_EQ(revsph::distributed::sum_over_processes(my_count),
            static_cast<std::int64_t>(values.size()));
}

TEST(Processes, ExactDoubleSumIsTheOneProcessSumForAnySplit) {
  const std::vector<double> values = terms();
  revsph::fixedpoint::ExactDoubleSum everything;
  revsph::fixedpoint::ExactDoubleSum mine;
  for (std::size_t i = 0; i < values.size(); ++i) {
    everything.add(values[i]);
    if (static_cast<int>(i % static_cast<std::size_t>(process_count())) == process_rank()) {
      mine.add(values[i]);
    }
  }
  const revsph::fixedpoint::ExactDoubleSum total = revsph::distributed::sum_over_processes(mine);
  EXPECT_TRUE(total.units() == everything.units());
  EXPECT_EQ(total.value(), everything.value());
}

TEST(Processes, MaximumAndMinimumAreTheOneProcessOnes) {
  const std::vector<double> values = terms();
  double largest = -1e300;
  double smallest = 1e300;
  double my_largest = -1e300;
  double my_smallest = 1e300;
  for (std::size_t i = 0; i < values.size(); ++i) {
    largest = std::max(largest, values[i]);
    smallest = std::min(smallest, values[i]);
    if (static_cast<int>(i % static_cast<std::size_t>(process_count())) == process_rank()) {
      my_largest = std::max(my_largest, values[i]);
      my_smallest = std::min(my_smallest, values[i]);
    }
  }
  EXPECT_EQ(revsph::distributed::max_over_processes(my_largest), largest);
  EXPECT_EQ(revsph::distributed::min_over_processes(my_smallest), smallest);
}

// Each process sets the bits of the flags i with i % count == rank among a fixed random set:
// the or over the processes is the whole set, as one process would have it.
TEST(Processes, BitwiseOrIsTheOneProcessOr) {
  std::mt19937_64 generator(777);
  const std::uint64_t all = generator();
  std::uint64_t mine = 0;
  for (int bit = 0; bit < 64; ++bit) {
    if (bit % process_count() == process_rank()) {
      mine |= all & (std::uint64_t{1} << bit);
    }
  }
  EXPECT_EQ(revsph::distributed::or_over_processes(mine), all);
}

// Bytes whose counts each process knows in advance (each sends rank + p + 1 bytes to process p,
// the byte value the sender's rank) arrive as with the exchange that sends the counts first.
TEST(Processes, ExchangeWithKnownCountsIsTheExchangeWithCounts) {
  const auto count = static_cast<std::size_t>(process_count());
  const auto me = static_cast<std::size_t>(process_rank());
  std::vector<std::size_t> send_bytes(count), receive_bytes(count);
  std::vector<std::byte> send;
  for (std::size_t p = 0; p < count; ++p) {
    send_bytes[p] = me + p + 1;
    receive_bytes[p] = p + me + 1;
    send.insert(send.end(), send_bytes[p], static_cast<std::byte>(me));
  }
  std::vector<std::size_t> received_bytes;
  const std::vector<std::byte> with_counts =
      revsph::distributed::exchange_bytes(send, send_bytes, received_bytes);
  const std::vector<std::byte> known = revsph::distributed::exchange_bytes(
      send, send_bytes, std::span<const std::size_t>(receive_bytes));
  EXPECT_EQ(received_bytes, receive_bytes);
  EXPECT_EQ(known, with_counts);
  std::size_t at = 0;
  for (std::size_t p = 0; p < count; ++p) {
    for (std::size_t b = 0; b < receive_bytes[p]; ++b) {
      ASSERT_EQ(known[at++], static_cast<std::byte>(p));
    }
  }
}

} // namespace
