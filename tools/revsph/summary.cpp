#include "tools/revsph/summary.hpp"

#include "core/build_info.hpp"
#include "core/memory.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <stdexcept>

namespace revsph::cli {

void write_summary(const std::filesystem::path& path, Simulation& simulation, const RunSummary& run,
                   const EnergyLog& energy) {
  const SimulationInfo& info = simulation.info();
  nlohmann::ordered_json summary;
  summary["case"] = info.case_name;
  summary["case_source"] = run.case_source;
  summary["overrides"] = run.overrides;
  summary["model"] = info.model;
  summary["dimension"] = info.dimension;
  summary["arithmetic"] = std::string(to_string(info.arithmetic));
  for (const ParticleCount& p : info.particles) {
    summary["particles"][p.particle_set] = p.count;
  }
  summary["dt"] = info.dt;
  summary["steps_requested"] = run.steps_requested;
  summary["steps"] = simulation.steps_taken();
  summary["time"] = simulation.time();
  summary["completed"] = !run.failure.has_value();
  if (run.failure) {
    summary["failure"] = *run.failure;
  }
  summary["wall_seconds"] = run.wall_seconds;
  const double particle_steps = static_cast<double>(info.moving_particle_count()) *
                                static_cast<double>(simulation.steps_taken());
  summary["particle_steps_per_second"] =
      run.wall_seconds > 0 ? particle_steps / run.wall_seconds : 0.0;
  summary["threads"] = run.threads;
  summary["peak_memory_bytes"] = peak_resident_bytes();
  summary["initial_hash"] = run.initial_hash;
  summary["final_hash"] = run.final_hash;
  if (!energy.empty()) {
    summary["energy"]["initial_total"] = energy.initial_total();
    summary["energy"]["final_total"] = energy.last().total();
    summary["energy"]["max_relative_error"] = energy.max_relative_error();
    for (const EnergyTerm& term : energy.last().terms) {
      summary["energy"]["final"][term.name] = term.value;
    }
  }
  summary["build"] = {{"version", build_info::version},
                      {"git_commit", build_info::git_commit},
                      {"compiler", build_info::compiler},
                      {"build_type", build_info::build_type},
                      {"flags", build_info::flags}};
  std::ofstream out(path);
  if (!out) {
    throw std::runtime_error("cannot write " + path.string());
  }
  out << summary.dump(2) << "\n";
}

} // namespace revsph::cli
