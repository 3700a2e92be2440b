#pragma once
// What the work estimate (work_estimate.hpp) misses, measured (docs/design/distributed.md,
// "Next", 4): the estimate counts pairs and own updates, but shtc's clamped base, a model's
// wall particles or a free surface cost more or less per pair than it says, and on a shared
// machine a process may simply run slower. Each process times its computing (its wall time
// minus its time inside MPI calls, where it waits for the others) between two cuts of the
// regions; a process whose estimated work took longer per unit than the mean gets its particles
// weighed up by that ratio at the next cut. The readings are combined on every process in the
// same order, so every process takes the same decision; the regions never change a bit of the
// results, only the speed.

#include "core/distributed/communication_tally.hpp"
#include "core/distributed/records_of_every_process.hpp"

#include <algorithm>
#include <chrono>
#include <span>
#include <vector>

namespace revsph::distributed {

// Whether the regions are also cut on measured times: `every_reading` cuts at every reading,
// however even (the tests: such cuts change no bit and every process takes them alike).
enum class TimeBalance { off, on, every_reading };

struct CostReading {
  double imbalance = 1.0; // the largest process's computing seconds over the mean
  double factor = 1.0;    // this process's seconds per unit of estimated work over the run's
  bool long_enough = false;
};

class MeasuredCost {
public:
  // `shortest_interval`: the mean computing seconds below which a reading is too noisy to act on.
  explicit MeasuredCost(double shortest_interval = 0.5) : shortest_(shortest_interval) {
    restart(0.0);
  }

  // A new interval from now, for regions whose estimated work on this process is `work`.
  void restart(double work) {
    start_ = std::chrono::steady_clock::now();
    communication_at_start_ = communication_tally().seconds;
    work_ = work;
  }

  // Every process's computing seconds and estimated work since the last restart (collective).
  CostReading read() const {
    struct Record {
      double seconds, work;
    };
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const Record mine{
        std::max(0.0, elapsed - (communication_tally().seconds - communication_at_start_)), work_};
    const std::vector<Record> all = records_of_every_process(std::span<const Record>(&mine, 1));
    double seconds = 0.0, work = 0.0, largest = 0.0;
    for (const Record& record : all) { // in rank order: the same sums on every process
      seconds += record.seconds;
      work += record.work;
      largest = std::max(largest, record.seconds);
    }
    CostReading reading;
    const double mean = seconds / static_cast<double>(all.size());
    // From the combined records only, so that every process decides alike.
    reading.long_enough = mean >= shortest_ && work > 0.0 && seconds > 0.0;
    if (reading.long_enough) {
      reading.imbalance = largest / mean;
      reading.factor = mine.work > 0.0 ? (mine.seconds / mine.work) / (seconds / work) : 1.0;
    }
    return reading;
  }

  // After a cut made on a reading: if the next reading is no better, wait twice as long before
  // acting on one again (the cut could not even the computing out); if it is, as before.
  void judge_last_cut(double imbalance_before, double imbalance_after) {
    shortest_ = imbalance_after < imbalance_before - 0.01 ? first_shortest_ : 2.0 * shortest_;
  }
  double shortest_interval() const { return shortest_; }

private:
  double shortest_;
  double first_shortest_ = shortest_;
  std::chrono::steady_clock::time_point start_;
  double communication_at_start_ = 0.0;
  double work_ = 0.0;
};

} // namespace revsph::distributed
