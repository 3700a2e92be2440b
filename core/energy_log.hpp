#pragma once
// energy.csv: one row per output step with every energy term, the total and two relative errors
// of the total (docs/verify.md, "Two energy errors"):
//   relative_error             |E(t) - E(0)| / S, S the larger of |E(0)| and the largest |term|
//                              recorded so far: the paper's |E - E(0)| / |E(0)| (paper 1, Fig. 8)
//                              for an isolated system whose terms are positive, and still a scale
//                              for one that starts at rest (E(0) = 0) and is driven (its terms
//                              then include the work done on it, counted negative);
//   mechanical_relative_error  |E(t) - E(0)| / M(t), M the energy that has moved so far
//                              (core/mechanical_energy_scale.hpp): the error a reader can judge
//                              when E(0) is mostly energy that never moves (WCSPH water at rest).
// E(0) is the first row's total or, for a restarted run, the total at the start of the original
// run. A run that continues another with its rows (docs/restart.md) replays them first: every
// scale and maximum then carries on as in the run that never stopped, and its rows follow
// theirs in the same file. (A restart without them starts the mechanical scale again from its
// first row's terms.)

#include "core/energy.hpp"
#include "core/logged_rows.hpp"
#include "core/mechanical_energy_scale.hpp"

#include <cstdint>
#include <fstream>
#include <optional>
#include <string>

namespace revsph {

class EnergyLog {
public:
  // Writes to `csv_path` if given; always keeps the error statistics.
  explicit EnergyLog(std::optional<std::string> csv_path,
                     std::optional<double> reference_total = std::nullopt);
  // Continues the rows `earlier` (what csv_path already holds, rows_before of the run continued):
  // replays them and appends to the file from there on.
  EnergyLog(std::optional<std::string> csv_path, std::optional<double> reference_total,
            const LoggedRows& earlier);

  void record(std::int64_t step, double time, const EnergyBudget& budget);

  bool empty() const { return !recorded_; }
  // E(0) for the relative error, if not the first record's total (a later half of a run).
  void set_reference_total(double total) { initial_total_ = total; }
  // A later half of the same experiment (verify's backward half): E(0), the initial terms and
  // both scales carry on from `earlier`, so that both halves are measured alike (the maxima of
  // the errors stay this half's own).
  void continue_from(const EnergyLog& earlier);
  double initial_total() const { return initial_total_.value_or(0.0); }
  double last_relative_error() const { return last_relative_error_; }
  double max_relative_error() const { return max_relative_error_; }
  double last_mechanical_relative_error() const { return last_mechanical_relative_error_; }
  // The largest |E(t) - E(0)| recorded (by this log) over the mechanical scale at its last
  // record: the
  // normalisation of paper 1's Fig. 5 (by the whole drop of the potential energy), which an
  // early record, taken before much energy has moved, cannot inflate.
  double max_mechanical_relative_error() const;
  double max_deviation() const { return max_deviation_; }
  double mechanical_scale() const { return mechanical_scale_.value(); }
  const EnergyBudget& last() const { return last_; }

private:
  // Updates every error statistic with one record.
  void observe(const EnergyBudget& budget);

  std::optional<std::ofstream> csv_;
  std::vector<std::string> earlier_terms_; // the term names of the rows continued, if any
  std::optional<double> initial_total_;
  bool recorded_ = false;
  double scale_ = 0.0;
  MechanicalEnergyScale mechanical_scale_;
  double max_deviation_ = 0.0;
  double last_relative_error_ = 0.0;
  double max_relative_error_ = 0.0;
  double last_mechanical_relative_error_ = 0.0;
  EnergyBudget last_;
};

} // namespace revsph
