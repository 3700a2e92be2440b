// Randomised robustness of case-file handling: thousands of mutants of the built-in cases go
// through the command line's sequence (tools/revsph/common.cpp: parse, --set overrides,
// read_run_settings, create_simulation, require_no_unknown_keys) and, when that succeeds, a few
// steps. Every mutant must end in one of three ways:
//
//   - a valid run setup (and steps that either run or stop with a SimulationFault),
//   - a CaseError (bad input, reported cleanly),
//   - a SimulationFault (a setup whose state overflows or leaves the domain).
//
// Anything else — another exception type, std::bad_alloc, a crash, a hang — fails the test with
// the seed, the mutant's number and its text. The mutations are byte edits (NUL, non-UTF-8,
// quotes, brackets, '=', newlines), line edits, numbers replaced by extreme ones, values replaced
// by other types, renamed keys, inserted keys and tables, truncation, random --set overrides, and
// combinations of these. Cases are made cheap (a coarse dr: a few hundred particles) and every
// setup is limited to a 64 MB memory budget, so absurd sizes are refused quickly.
//
// A valid setup must also have a non-negative run length, and every key the readers asked for,
// valid mutant or not, must be declared in the key tables (the reference of revsph cases
// --keys). A mutant taking more than the per-mutant limit (2 s of CPU time in a Release build)
// fails the test; one that hangs is caught by a watchdog that prints it and aborts, and a crash
// or sanitizer report prints it too.
//
// Reproduce or extend a run with REVSPH_CASE_FUZZ_SEED=<seed> and REVSPH_CASE_FUZZ_MUTANTS=<n>
// (per test); REVSPH_CASE_FUZZ_SLOW_MS=<ms> prints every mutant slower than that.

#include "core/case_file.hpp"
#include "core/case_keys.hpp"
#include "core/fault.hpp"
#include "core/model_registry.hpp"
#include "core/run_settings.hpp"
#include "core/simulation.hpp"
#include "core/threads.hpp"

#include "case_mutator.hpp"
#include "case_text.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <mutex>
#include <new>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <time.h>
#include <typeinfo>
#include <unistd.h>
#include <vector>

#if defined(__SANITIZE_ADDRESS__)
#define REVSPH_FUZZ_SANITIZED 1
#else
#define REVSPH_FUZZ_SANITIZED 0
#endif

// Provided by every sanitizer runtime (ASan, UBSan, ...) and absent otherwise.
extern "C" __attribute__((weak)) void __sanitizer_set_death_callback(void (*callback)(void));

namespace revsph {
namespace {

using testing::Mutator;

using Clock = std::chrono::steady_clock;

double thread_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

constexpr std::uint64_t default_seed = 20240611;
constexpr std::size_t memory_budget_bytes = std::size_t{64} << 20;
constexpr std::int64_t steps_per_setup = 3;
// A mutant is one parse and at most a 64 MB setup plus a few steps: well below a second in a
// Release build. Sanitized builds run several times slower. Measured as CPU time of the test's
// thread (the simulation runs on it, with one OpenMP thread), so that a loaded machine does not
// make a mutant look slow; a mutant that blocks instead is caught by the watchdog.
constexpr double per_mutant_limit_seconds = REVSPH_FUZZ_SANITIZED ? 20.0 : 2.0;
// A mutant still running after this long hangs: print it and abort (a failed test, not a
// silently stuck one).
constexpr double watchdog_seconds = REVSPH_FUZZ_SANITIZED ? 120.0 : 30.0;
constexpr int max_reported_failures = 5;

std::uint64_t env_or(const char* name, std::uint64_t fallback) {
  const char* value = std::getenv(name);
  if (value == nullptr || *value == '\0') {
    return fallback;
  }
  return std::strtoull(value, nullptr, 0);
}

// The text with bytes that would garble a terminal written as \xNN (newlines kept).
std::string printable(std::string_view text) {
  std::ostringstream out;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n' || (byte >= 0x20 && byte < 0x7f)) {
      out << c;
    } else {
      out << "\\x" << std::hex << std::setw(2) << std::setfill('0') << static_cast<int>(byte)
          << std::dec;
    }
  }
  return out.str();
}

// ---------------------------------------------------------------------------------------------
// Crash and hang reporting: the mutant being run, printed from a signal handler, a sanitizer's
// death callback or the watchdog.

std::mutex current_mutex;
std::string current_report; // "seed ..., mutant ...:\n<text>"
char crash_buffer[1 << 16];
std::atomic<std::size_t> crash_length{0};

void set_current(const std::string& report) {
  const std::size_t length = std::min(report.size(), sizeof crash_buffer - 1);
  crash_length.store(0);
  std::memcpy(crash_buffer, report.data(), length);
  crash_length.store(length);
  const std::lock_guard<std::mutex> lock(current_mutex);
  current_report = report;
}

void write_current_mutant() {
  static const char header[] = "\n*** case_fuzz_test: the program died while running ";
  ssize_t ignored = ::write(STDERR_FILENO, header, sizeof header - 1);
  ignored = ::write(STDERR_FILENO, crash_buffer, crash_length.load());
  ignored = ::write(STDERR_FILENO, "\n", 1);
  (void)ignored;
}

extern "C" void on_fatal_signal(int signal_number) {
  write_current_mutant();
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

void install_crash_reporting() {
  static bool installed = false;
  if (installed) {
    return;
  }
  installed = true;
  if (__sanitizer_set_death_callback != nullptr) {
    // A sanitizer's report ends the program without a signal; this runs before it exits.
    __sanitizer_set_death_callback(write_current_mutant);
  }
  if (!REVSPH_FUZZ_SANITIZED) { // AddressSanitizer handles (and reports) these itself
    for (const int signal_number : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) {
      std::signal(signal_number, on_fatal_signal);
    }
  }
}

// Aborts the process (after printing the current mutant) if one mutant runs longer than
// watchdog_seconds.
class Watchdog {
public:
  Watchdog() : thread_([this] { run(); }) {}
  ~Watchdog() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
  }
  void start_mutant() {
    const std::lock_guard<std::mutex> lock(mutex_);
    ++generation_;
    started_ = Clock::now();
  }

private:
  void run() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stop_) {
      const std::uint64_t generation = generation_;
      const auto deadline = started_ + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(watchdog_seconds));
      wake_.wait_until(lock, deadline, [&] { return stop_ || generation_ != generation; });
      if (!stop_ && generation_ == generation && generation != 0 && Clock::now() >= deadline) {
        std::string report;
        {
          const std::lock_guard<std::mutex> current_lock(current_mutex);
          report = current_report;
        }
        std::cerr << "\n*** case_fuzz_test: a mutant has run for more than " << watchdog_seconds
                  << " s (a hang): " << report << std::endl;
        std::abort();
      }
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::uint64_t generation_ = 0;
  Clock::time_point started_ = Clock::now();
  std::thread thread_;
};

// ---------------------------------------------------------------------------------------------
// Running a mutant.

enum class Outcome { ran, faulted_in_setup, faulted_in_steps, case_error };

struct Overrides {
  std::vector<std::pair<std::string, std::string>> items;
};

// What the command line does with a case (tools/revsph/common.cpp), then a few steps.
// Every key the readers asked a mutant for is in the reference (revsph cases --keys MODEL), also
// when the mutant is refused: the key tables are complete for what the readers accept. The
// tables are the ones create_simulation attached (a mutant may name another model), else those
// of the built-in cases' model.
void require_declared(const CaseFile& case_file) {
  std::vector<const KeyTable*> tables = case_file.key_tables();
  if (tables.empty()) {
    tables = {&common_case_keys(), &model_registry().find("wcsph")->keys()};
  }
  for (const std::string& key : case_file.accessed_keys()) {
    const std::string pattern = key_pattern(key);
    bool declared = false;
    for (const KeyTable* table : tables) {
      declared = declared || table->find(pattern) != nullptr || table->declares_table(pattern);
    }
    if (!declared) {
      throw std::logic_error("the readers asked for \"" + key + "\", which no key table declares");
    }
  }
}

Outcome run_mutant(const std::string& text, const Overrides& overrides, Arithmetic arithmetic) {
  std::unique_ptr<Simulation> simulation;
  RunSettings settings;
  std::optional<CaseFile> case_file;
  // Checked however the setup ends (the destructor runs while a CaseError propagates, so the
  // check is done explicitly on every path).
  auto checked = [&](Outcome outcome) {
    if (case_file) {
      require_declared(*case_file);
    }
    return outcome;
  };
  try {
    case_file.emplace(CaseFile::parse(text, "mutant.toml"));
    for (const auto& [key, value] : overrides.items) {
      case_file->set(key, value);
    }
    settings = read_run_settings(*case_file);
    SimulationOptions options;
    options.arithmetic = arithmetic;
    options.memory_budget_bytes = memory_budget_bytes;
    simulation = create_simulation(*case_file, options);
    case_file->require_no_unknown_keys();
  } catch (const CaseError&) {
    return checked(Outcome::case_error);
  } catch (const SimulationFault&) {
    return checked(Outcome::faulted_in_setup);
  }
  checked(Outcome::ran);
  // A valid [run] length is never negative (what `revsph run` would take).
  if (settings.length.given() && settings.length.steps_for(simulation->info().dt) < 0) {
    throw std::logic_error("a valid case has a negative run length");
  }
  try {
    simulation->advance(steps_per_setup);
    simulation->energy();
  } catch (const SimulationFault&) {
    return Outcome::faulted_in_steps;
  }
  return Outcome::ran;
}

std::string describe_current_exception() {
  try {
    throw;
  } catch (const std::bad_alloc& error) {
    return std::string("std::bad_alloc: ") + error.what();
  } catch (const std::exception& error) {
    return std::string("an exception of type ") + typeid(error).name() + ": " + error.what();
  } catch (...) {
    return "an exception of unknown type";
  }
}

// The case text without its comments (the built-in cases have no '#' inside strings).
std::string without_comments(const std::string& text) {
  std::string result;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    line = line.substr(0, line.find('#'));
    while (!line.empty() && line.back() == ' ') {
      line.pop_back();
    }
    if (!line.empty()) {
      result += line + "\n";
    }
  }
  return result;
}

struct FuzzSettings {
  std::string builtin_case;
  std::string coarse_from; // a line of the built-in case ...
  std::string coarse_to;   // ... replaced to make it cheap
  std::uint64_t default_mutants = 0;
  std::uint64_t seed_offset = 0;  // a different stream per test
  bool floating_point_too = true; // false for a model that runs in fixed point only
  // A point file (core/point_file.hpp) the case reads: `point_block` replaces `point_block_from`
  // in the case (without a point file, only that replacement), and each mutant reads `point_file` (mutated too, a third of the time), written
  // to a file whose absolute path replaces POINT_FILE in `point_block`.
  std::string point_block_from;
  std::string point_block;
  std::string point_file;
};

// A file for the point file of a fuzz test, removed at the end.
struct PointFileOnDisk {
  std::filesystem::path path = std::filesystem::temp_directory_path() /
                               ("revsph-case-fuzz-" + std::to_string(::getpid()) + ".csv");
  void write(const std::string& text) const { std::ofstream(path, std::ios::binary) << text; }
  ~PointFileOnDisk() { std::filesystem::remove(path); }
};

void fuzz(const FuzzSettings& settings) {
  install_crash_reporting();
  const std::uint64_t seed = env_or("REVSPH_CASE_FUZZ_SEED", default_seed) + settings.seed_offset;
  const std::uint64_t mutant_count = env_or("REVSPH_CASE_FUZZ_MUTANTS", settings.default_mutants);
  // Diagnostics: print every mutant slower than this many milliseconds.
  const std::uint64_t slow_report_ms = env_or("REVSPH_CASE_FUZZ_SLOW_MS", 0);
  SCOPED_TRACE("seed " + std::to_string(seed) +
               " (REVSPH_CASE_FUZZ_SEED=" + std::to_string(seed - settings.seed_offset) + ")");

  // One thread: the cases are tiny, and OpenMP barriers on a loaded machine (ctest -j, other
  // builds) would make the per-mutant times meaningless.
  const int threads = thread_count();
  set_thread_count(1);
  struct RestoreThreads {
    int threads;
    ~RestoreThreads() { set_thread_count(threads); }
  } restore{threads};

  std::string base = testing::replaced_once(testing::builtin_case_text(settings.builtin_case),
                                            settings.coarse_from, settings.coarse_to);
  const PointFileOnDisk point_file;
  if (!settings.point_block.empty()) {
    base = testing::replaced_once(
        base, settings.point_block_from,
        settings.point_file.empty()
            ? settings.point_block
            : testing::replaced_once(settings.point_block, "POINT_FILE", point_file.path.string()));
    point_file.write(settings.point_file);
  }
  // Most mutants start from the case without its comments, so that edits land on what is read.
  const std::string base_without_comments = without_comments(base);
  // The unmutated coarse case must be a valid, cheap setup, or the mutants test little.
  ASSERT_EQ(run_mutant(base, {}, Arithmetic::fixed), Outcome::ran);
  ASSERT_EQ(run_mutant(base_without_comments, {}, Arithmetic::fixed), Outcome::ran);

  Mutator mutator(seed);
  Watchdog watchdog;
  std::array<std::uint64_t, 4> outcomes{};
  int failures = 0;
  double slowest = 0.0; // CPU seconds
  double slowest_wall = 0.0;
  std::uint64_t slowest_mutant = 0;
  const auto started = Clock::now();
  std::uint64_t done = 0;
  for (std::uint64_t m = 0; m < mutant_count && failures < max_reported_failures; ++m, ++done) {
    std::string text = mutator.chance(0.8) ? base_without_comments : base;
    for (std::size_t n = 1 + (mutator.chance(0.4) ? mutator.below(6) : 0); n > 0; --n) {
      mutator.mutate(text);
    }
    Overrides overrides;
    if (mutator.chance(0.1)) {
      for (std::size_t n = 1 + mutator.below(2); n > 0; --n) {
        overrides.items.push_back(mutator.random_override());
      }
    }
    std::string points = settings.point_file;
    if (!points.empty()) {
      if (mutator.chance(0.3)) {
        mutator.mutate(points);
      }
      point_file.write(points);
    }
    const Arithmetic arithmetic = settings.floating_point_too && mutator.chance(0.2)
                                      ? Arithmetic::floating
                                      : Arithmetic::fixed;

    std::ostringstream report;
    report << "seed " << seed << ", mutant " << m << " (" << to_string(arithmetic) << " arithmetic";
    for (const auto& [key, value] : overrides.items) {
      report << ", --set '" << printable(key) << "=" << printable(value) << "'";
    }
    report << "), case text:\n" << printable(text) << "\n--- end of case text";
    if (points != settings.point_file) {
      report << "\npoint file:\n" << printable(points) << "\n--- end of point file";
    }
    set_current(report.str());
    watchdog.start_mutant();

    const auto mutant_started = Clock::now();
    const double cpu_started = thread_cpu_seconds();
    try {
      ++outcomes[static_cast<std::size_t>(run_mutant(text, overrides, arithmetic))];
    } catch (...) {
      ++failures;
      ADD_FAILURE() << "mutant ended with " << describe_current_exception()
                    << " (allowed: success, revsph::CaseError, revsph::SimulationFault); "
                    << report.str();
    }
    const double seconds = thread_cpu_seconds() - cpu_started;
    const double wall = std::chrono::duration<double>(Clock::now() - mutant_started).count();
    if (seconds > slowest) {
      slowest = seconds;
      slowest_wall = wall;
      slowest_mutant = m;
    }
    if (slow_report_ms > 0 && seconds * 1000.0 > static_cast<double>(slow_report_ms)) {
      std::cout << "slow mutant: " << seconds * 1000.0 << " ms CPU, " << report.str() << "\n";
    }
    if (seconds > per_mutant_limit_seconds) {
      ++failures;
      ADD_FAILURE() << "mutant took " << seconds << " s of CPU time (limit "
                    << per_mutant_limit_seconds << " s); " << report.str();
    }
  }
  const double total = std::chrono::duration<double>(Clock::now() - started).count();
  std::cout << settings.builtin_case << ": " << done << " mutants (seed " << seed << ") in "
            << total << " s: " << outcomes[0] << " ran, " << outcomes[3] << " CaseError, "
            << outcomes[1] << " SimulationFault in setup, " << outcomes[2]
            << " SimulationFault while stepping; slowest mutant " << slowest_mutant << ": "
            << slowest * 1000.0 << " ms CPU (" << slowest_wall * 1000.0 << " ms wall)\n";
  // The mutants must reach beyond the parser: a fair share builds and steps a simulation.
  if (failures == 0 && mutant_count >= 1000) {
    EXPECT_GT(outcomes[0] + outcomes[1] + outcomes[2], mutant_count / 20);
  }
}

TEST(CaseFuzz, MutantsOfDambreakSmall2D) {
  // dr 0.1: 200 fluid and about 150 wall particles.
  fuzz({"dambreak-small", "\ndr = 0.02", "\ndr = 0.1", 12000, 0});
}

// A user's fluid from a point file (core/point_file.hpp) with initial velocities and masses: 200
// particles on the 0.1 m lattice of the coarse dambreak-small.
std::string dambreak_fluid_points() {
  std::ostringstream csv;
  csv << std::setprecision(17) << "x [m], y [m], velocity_x [m/s], velocity_y [m/s], mass [kg/m]\n";
  for (int row = 0; row < 20; ++row) {
    for (int column = 0; column < 10; ++column) {
      csv << 0.05 + 0.1 * column << ", " << 0.05 + 0.1 * row << ", " << 0.01 * (row % 3) << ", "
          << -0.02 * (column % 2) << ", " << 10.0 - 0.01 * row << "\n";
    }
  }
  return csv.str();
}

TEST(CaseFuzz, MutantsOfDambreakSmallFromAPointFile) {
  FuzzSettings settings{"dambreak-small", "\ndr = 0.02", "\ndr = 0.1", 6000, 11};
  settings.point_block_from =
      "shape = \"box\"\nlattice = \"square\"\nmin = [0.0, 0.0]\nmax = [1.0, 2.0]";
  settings.point_block = "shape = \"points\"\nfile = \"POINT_FILE\"\nparticle_volume = 0.01";
  settings.point_file = dambreak_fluid_points();
  fuzz(settings);
}

// An obstacle from a closed STL surface (core/stl_region.hpp, CGAL), in the 3D dam break: a
// 0.25 m cube on the floor, 8 wall particles at the coarse 0.125 m spacing.
std::string obstacle_stl() {
  const char* corners[] = {"0.5 0 0",    "0.75 0 0",    "0.5 0.25 0",    "0.75 0.25 0",
                           "0.5 0 0.25", "0.75 0 0.25", "0.5 0.25 0.25", "0.75 0.25 0.25"};
  const int triangles[12][3] = {{0, 2, 1}, {2, 3, 1}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                {2, 6, 3}, {6, 7, 3}, {0, 4, 2}, {4, 6, 2}, {1, 3, 5}, {3, 7, 5}};
  std::string text = "solid obstacle\n";
  for (const auto& t : triangles) {
    text += "facet normal 0 0 0\nouter loop\n";
    for (const int v : t) {
      text += std::string("vertex ") + corners[v] + "\n";
    }
    text += "endloop\nendfacet\n";
  }
  return text + "endsolid obstacle\n";
}

TEST(CaseFuzz, MutantsOfDambreakSmall3DWithAnStlObstacle) {
  FuzzSettings settings{"dambreak-3d-small", "dr = 0.025", "dr = 0.125", 3000, 12};
  settings.point_block_from = "[run]";
  settings.point_block =
      "[[particles]]\nkind = \"wall\"\nshape = \"stl\"\nfile = \"POINT_FILE\"\n[run]";
  settings.point_file = obstacle_stl();
  fuzz(settings);
}

// A periodic domain (core/periodic_box.hpp): the dam break periodic along x, across its tank's
// side walls (no point file: the block replacement only adds the key).
TEST(CaseFuzz, MutantsOfDambreakSmallPeriodicInX) {
  FuzzSettings settings{"dambreak-small", "\ndr = 0.02", "\ndr = 0.1", 3000, 13};
  settings.point_block_from = "[domain]";
  settings.point_block = "[domain]\nperiodic = \"x\"";
  fuzz(settings);
}

TEST(CaseFuzz, MutantsOfDambreakSettling) {
  // The artificial viscosity and step.splitting of the wcsph model (issue 33 item 5); dr 0.1:
  // 50 fluid and about 60 wall particles.
  fuzz({"dambreak-settling", "dr = 0.02 ", "dr = 0.1 ", 3000, 14});
}

TEST(CaseFuzz, MutantsOfExpansionSmall) {
  // The entropic model (fixed point only); dr 0.1: 100 gas and about 130 wall particles.
  fuzz({"expansion-small", "dr = 0.05", "dr = 0.1", 8000, 2, false});
}

TEST(CaseFuzz, MutantsOfCavitySmall) {
  // The entropic model's walls: thermal blocks and their temperatures, no-slip, the pairwise
  // conduction, gravity; dr 0.1: 100 gas and about 130 wall particles.
  fuzz({"cavity-small", "dr = 0.05", "dr = 0.1", 8000, 3, false});
}

TEST(CaseFuzz, MutantsOfHyperbolicSmall) {
  // The entropic model's hyperbolic heat conduction: particles at rest, the flux energy, the
  // temperature gradient, the stiffened gas; dr 0.1: 50 gas particles.
  fuzz({"hyperbolic-small", "dr = 0.05", "dr = 0.1", 8000, 4, false});
}

TEST(CaseFuzz, MutantsOfDropletSmall) {
  // The superfluid model: random v, v_s and s, free surfaces; dr 2 mm: 64 particles.
  fuzz({"droplet-small", "dr = 1.0e-3", "dr = 2.0e-3", 8000, 5});
}

TEST(CaseFuzz, MutantsOfSecondSoundSmall) {
  // The superfluid model's entropy wave on a Vogel spiral; dr 1 mm: about 100 particles.
  fuzz({"second-sound-small", "dr = 3.3333333333333335e-4", "dr = 1.0e-3", 4000, 6});
}

TEST(CaseFuzz, MutantsOfCoolerSmall) {
  // The superfluid model's absorbing cooler (walls with their own superflow velocity in the
  // reversible pair terms); dr 2 mm: 64 fluid and about 100 wall particles.
  fuzz({"cooler-small", "dr = 1.0e-3", "dr = 2.0e-3", 3000, 10});
}

TEST(CaseFuzz, MutantsOfRotatingCylinderSmall) {
  // The two-fluid model: a random mixture, turning walls, viscosity, mutual friction, the spin
  // term; dr 10 um: about 300 fluid and 130 wall particles.
  fuzz({"rotating-cylinder-small", "dr = 6.25e-6", "dr = 1.0e-5", 4000, 7});
}

TEST(CaseFuzz, MutantsOfRotatingCylinderSmallInterpenetrating) {
  // The same with interpenetrating phases (every particle at rho_s + rho_n, the phases' volumes,
  // the draw's fraction checked): the paper's resolution of the small case, 800 fluid particles.
  fuzz({"rotating-cylinder-small", "[physics]", "[physics]\nphases = \"interpenetrating\"", 1500,
        9});
}

TEST(CaseFuzz, MutantsOfRayleighTaylorSmall) {
  // The two-fluid model's interface, gravity and its time-step limit; dr 6.25 um: 512 fluid and
  // about 300 wall particles.
  fuzz({"rayleigh-taylor-small", "dr = 4.1666666666666667e-6", "dr = 6.25e-6", 4000, 8});
}

TEST(CaseFuzz, MutantsOfDambreakSmall3D) {
  // dr 0.125: 16 fluid and about 300 wall particles.
  fuzz({"dambreak-3d-small", "dr = 0.025", "dr = 0.125", 8000, 1});
}

} // namespace
} // namespace revsph
