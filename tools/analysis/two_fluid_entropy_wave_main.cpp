// revsph_two_fluid_entropy_wave: one run of paper 5's entropy-wave benchmark (sec. V.2, Figs.
// 7-8; two_fluid_entropy_wave.hpp). Writes
//   PREFIX.csv        one summary row: method, speed, fluctuation, dl_over_l, particles (per
//                     side), dt, steps, mean_error_percent (the paper's E_r at t_end),
//                     max_error_percent, wall_seconds, mode_amplitude (least squares, at t_end),
//                     exact_amplitude (cos(lambda t_end)), off_mode_error_percent (E_r of the part
//                     of S outside the mode)
//   PREFIX_probe.csv  time, S, S_exact at the particle of the lattice cell holding --probe
// and prints the summary to stdout. Run it on one thread (OMP_NUM_THREADS=1): Eigen's sparse
// products use OpenMP otherwise. Figure: /usr/bin/python3 tools/plots/two_fluid_entropy_wave.py

#include "two_fluid_entropy_wave.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

namespace {

using namespace revsph::analysis;

std::string summary_header() {
  return "method,speed,fluctuation,dl_over_l,particles,dt,steps,mean_error_percent,"
         "max_error_percent,wall_seconds,mode_amplitude,exact_amplitude,off_mode_error_percent,"
         "support_over_l,literal_error_percent";
}

std::string summary_row(const EntropyWaveOptions& options, const EntropyWaveResult& result,
                        double wall_seconds) {
  char line[512];
  const double exact_amplitude = std::cos(5.0 * std::numbers::pi * options.speed * options.t_end);
  std::snprintf(line, sizeof line,
                "%s,%.10g,%.10g,%.10g,%d,%.10g,%ld,%.10g,%.10g,%.3f,%.12g,%.12g,%.10g,%.10g,%.10g",
                name_of(options.method).data(), options.speed, options.fluctuation_percent,
                result.displacement / result.spacing, options.per_side, result.dt, result.steps,
                result.mean_error_percent, result.max_error_percent, wall_seconds,
                result.mode_amplitude, exact_amplitude, result.off_mode_error_percent,
                options.support_over_l, result.literal_error_percent);
  return line;
}

} // namespace

int main(int argc, char** argv) {
  CLI::App app{"Paper 5's entropy-wave benchmark (sec. V.2): the wave equation on the unit "
               "square, mode (4, 3), with an SPH, Brookshaw or finite-difference Laplacian"};
  EntropyWaveOptions options;
  std::string method = "sph";
  std::string prefix = "entropy_wave";
  std::vector<double> probe{options.probe[0], options.probe[1]};
  app.add_option("--method", method, "sph (App. A), brookshaw (eq. 14 times 2) or fd (5-point)")
      ->check(CLI::IsMember({"sph", "brookshaw", "fd"}))
      ->capture_default_str();
  app.add_option("--speed", options.speed, "c [m/s] (the paper: 135 and 20)")
      ->capture_default_str();
  app.add_option("--fluctuation", options.fluctuation_percent,
                 "volume fluctuation rate dD [%]: dl = l (sqrt(1 + dD/100) - 1); 0 for fd")
      ->capture_default_str();
  app.add_option("--particles", options.per_side, "particles per side")->capture_default_str();
  app.add_option("--seed", options.seed, "seed of the displacement directions")
      ->capture_default_str();
  app.add_option("--support", options.support_over_l,
                 "the Wendland quintic's support radius in spacings l (the paper names none)")
      ->capture_default_str();
  app.add_option("--t-end", options.t_end, "end time [s]")->capture_default_str();
  app.add_option("--dt-factor", options.dt_factor, "dt = factor l / c")->capture_default_str();
  app.add_option("--probe-every", options.probe_every, "steps between probe samples")
      ->capture_default_str();
  app.add_option("--probe", probe,
                 "the probe: the particle of the lattice cell holding this point (x y)")
      ->expected(2)
      ->capture_default_str();
  app.add_option("--out", prefix, "writes PREFIX.csv and PREFIX_probe.csv")->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    options.method = wave_laplacian_named(method);
    options.probe = {probe[0], probe[1]};
    const auto start = std::chrono::steady_clock::now();
    const EntropyWaveResult result = entropy_wave(options);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    const std::string row = summary_row(options, result, wall);
    std::ofstream summary(prefix + ".csv");
    summary << summary_header() << '\n' << row << '\n';
    std::ofstream series(prefix + "_probe.csv");
    series << "# probe particle at (" << result.probe_position[0] << ", "
           << result.probe_position[1] << ")\ntime,S,S_exact\n";
    for (std::size_t k = 0; k < result.probe_time.size(); ++k) {
      char line[128];
      std::snprintf(line, sizeof line, "%.10g,%.12g,%.12g\n", result.probe_time[k],
                    result.probe_value[k], result.probe_exact[k]);
      series << line;
    }
    if (!summary || !series) {
      std::cerr << "revsph_two_fluid_entropy_wave: cannot write " << prefix << ".csv or " << prefix
                << "_probe.csv\n";
      return 1;
    }
    std::cout << summary_header() << '\n' << row << '\n';
  } catch (const std::invalid_argument& e) {
    std::cerr << "revsph_two_fluid_entropy_wave: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "revsph_two_fluid_entropy_wave: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
