#pragma once
// The model-independent sections of a case file:
//
//   name = "dambreak-small"     optional; default the file name
//   [run]
//   steps = 1000                or t_end = 1.0 (s): how far `revsph run` goes by default
//   [output]
//   energy_every = 100          steps between rows of energy.csv
//   snapshot_every = 1000       steps between snapshots (0: only at the start and the end)
//   snapshot_interval = 0.5     simulated seconds between snapshots (with or instead of the above)
//   progress_interval = 10.0    seconds between progress lines when not on a terminal

#include "core/case_file.hpp"
#include "core/simulation.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace revsph {

struct RunLength {
  std::optional<std::int64_t> steps;
  std::optional<double> t_end;

  // Steps to take for time step dt: t_end / dt rounded to the nearest integer.
  std::int64_t steps_for(double dt) const;
  bool given() const { return steps.has_value() || t_end.has_value(); }
};

struct RunSettings {
  std::string name;
  RunLength length;
  std::int64_t energy_every = 100;
  std::int64_t snapshot_every = 0;
  double snapshot_interval = 0.0; // s; 0: none
  double progress_interval = 10.0;
};

RunSettings read_run_settings(const CaseFile& case_file);

// The case's `name`, or the file name without its extension.
std::string case_name(const CaseFile& case_file);

// What every set-up records first about its simulation (core/simulation.hpp): the case's name,
// the model, the dimension, the arithmetic and the time step; the model adds its set-up report.
SimulationInfo simulation_info(const CaseFile& case_file, std::string_view model, int dimension,
                               Arithmetic arithmetic, double dt);

} // namespace revsph
