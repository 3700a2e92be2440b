#pragma once
// Whether a run stayed healthy (docs/running.md, "Health checks"): checks every model gets, made
// at each energy record, against limits in the case's [health] table:
//
//   energy error     energy.csv's relative_error, |E - E(0)| over the larger of |E(0)| and the
//                    largest term: the whole budget, the energy exchanged with the outside
//                    included (core/energy_log.hpp); a run that makes energy takes it towards 1,
//                    a budget closed only to first order (shtc's "matched" relaxation) to 0.2;
//   max|v| / c       the largest speed of a moving particle over the sound speed: a weakly
//                    compressible flow is far below 1, a gas expanding into vacuum reaches
//                    2 / (gamma - 1), 3 for gamma = 5/3, and a run that blows up far more;
//   merged pairs     pairs of particles closer than a millionth of dr (core/close_pairs.hpp):
//                    coincident, as the set-up refuses particles of two blocks to be; a pair
//                    that close has merged (nothing pushes it apart), while a chance pass that
//                    close is some 10^4 times rarer than one within dr/100 (the shipped dam
//                    break's closest passes).
//
// Pairs closer than a tenth of dr (close_pairs) are counted too, for the record: flows without
// anything wrong pass that close (docs/running.md).
//
// A check crossed gives one warning line, the first time, and makes the run unhealthy
// (summary.json's healthy and health_reasons; `revsph run --strict` exits with status 3).

#include "core/health_limits.hpp"
#include "core/logged_rows.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace revsph {

// The columns of diagnostics.csv the checks add (unit "1").
inline constexpr const char* speed_over_c_column = "speed_over_c";
inline constexpr const char* close_pairs_column = "close_pairs";
inline constexpr const char* merged_pairs_column = "merged_pairs";

// One record's readings; a check without its reading (a model without a sound speed or a dr) is
// not made.
struct HealthReading {
  std::optional<double> energy_error;
  std::optional<double> speed_over_c;
  std::optional<std::uint64_t> merged_pairs;
  std::optional<std::uint64_t> close_pairs; // named in the merged pairs' warning, not checked
};

class RunHealth {
public:
  explicit RunHealth(const HealthLimits& limits);

  // The warning lines of the checks this record crosses for the first time
  // ("warning: step 1200, t = 0.431 s: max|v|/c = 3.1 above health.max_speed_over_c = 1 …").
  std::vector<std::string> observe(std::int64_t step, double time, const HealthReading& reading);
  // The records of the run a run continues (energy.csv's and diagnostics.csv's rows it keeps),
  // observed without warnings: those were the earlier run's to give.
  void replay(const LoggedRows& energy_rows, const LoggedRows& diagnostics_rows);

  bool healthy() const;
  // One line per check crossed: what, the largest value reached, the limit, and where it was
  // first crossed.
  std::vector<std::string> reasons() const;

private:
  struct Check {
    double limit = 0.0;
    bool crossed = false;
    std::int64_t first_step = 0;
    double first_time = 0.0;
    double largest = 0.0;
  };
  enum Index { energy_error, speed_over_c, merged_pairs };
  // Observes `value` for one check; true if it crosses the limit here for the first time.
  bool observe_one(Check& check, double value, std::int64_t step, double time);

  double close_pair_fraction_;
  double merged_pair_fraction_;
  std::array<Check, 3> checks_;
};

} // namespace revsph
