// The revsph binary on bad input: exit status 2, exactly one line on stderr naming the file, the
// key and the reason, nothing on stdout, and nothing written.
//
// Every run happens in a fresh temporary working directory that holds only the case file, so a
// stray file (a default out/ directory, a log) would show up as well as the --out directory.

#include "core/model_registry.hpp"

#include "case_text.hpp"
#include "cli_sandbox.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::string dambreak_small_text() {
  return revsph::testing::builtin_case_text("dambreak-small");
}

using namespace revsph::testing;

// ---------------------------------------------------------------------------------------------
// One edit of the built-in case per defect, run with `revsph run`.

struct Defect {
  std::string name; // test-name suffix
  std::string from; // text of the built-in case to replace (must occur once)
  std::string to;
  std::string key;                       // must appear as "<file>: <key>: "
  std::vector<std::string> reason_parts; // must appear in the message
  std::vector<std::string> extra_arguments = {};
};

std::ostream& operator<<(std::ostream& out, const Defect& defect) {
  return out << defect.name;
}

const std::vector<Defect>& defects() {
  static const std::vector<Defect> all = {
      {"syntax_error", "\ndr = 0.02", "\ndr = = 0.02", "", {"syntax error at line @LINE@,"}},
      // Overlapping blocks (issue 33's fault list): fluid on fluid was accepted silently, fluid
      // over a wall ended in an overflow that did not say why.
      {"overlapping_fluid_blocks",
       "\n[run]",
       "\n[[particles]]\nkind = \"fluid\"\nshape = \"box\"\nlattice = \"square\"\nmin = [0.5, "
       "0.5]\nmax = [0.7, 0.7]\n\n[run]",
       "particles[2]",
       {"lies on particle", "of particles[0]", "the blocks overlap"}},
      {"fluid_block_over_the_wall",
       "\n[run]",
       "\n[[particles]]\nkind = \"fluid\"\nshape = \"box\"\nlattice = \"square\"\nmin = [1.5, "
       "-0.1]\nmax = [1.7, 0.3]\n\n[run]",
       "particles[2]",
       {"lies on particle", "of particles[1]", "the blocks overlap"}},
      {"syntax_error_duplicate_key",
       "\ndr = 0.02",
       "\ndr = 0.02\ndr = 0.03",
       "",
       {"syntax error at line @LINE@,"}},
      {"unknown_key",
       "\ndr = 0.02",
       "\ndr = 0.02\ndrr = 0.02",
       "discretisation.drr",
       {"unknown key (line @LINE@; every key: revsph cases --keys wcsph)"}},
      {"unknown_key_in_particles_block",
       "kind = \"fluid\"",
       "kind = \"fluid\"\ncolour = \"blue\"",
       "particles[0].colour",
       {"unknown key (line @LINE@; every key: revsph cases --keys wcsph)"}},
      {"missing_required_key",
       "sound_speed = 120.0",
       "",
       "physics.sound_speed",
       {"missing required key"}},
      // A misspelt required key is named as the unknown key it is, with the suggestion (it was
      // "missing required key" on the real one: issue 33's fault list).
      {"misspelt_required_key",
       "\ndr = 0.02",
       "\ndx = 0.02",
       "discretisation.dx",
       {"unknown key (line @LINE@; every key: revsph cases --keys wcsph)",
        "; did you mean discretisation.dr?"}},
      {"misspelt_table",
       "[discretisation]",
       "[discretization]",
       "discretization.dr",
       {"unknown key (line ", "; did you mean discretisation.dr?"}},
      // A --set value's error says that the value came from the command line.
      {"set_value_of_the_wrong_type",
       "\ndr = 0.02",
       "\ndr = 0.02",
       "discretisation.dr",
       {"expected a number, got a string (given with --set)"},
       {"--set", "discretisation.dr=abc"}},
      {"missing_dt", "courant_number = 0.2", "", "discretisation.dt", {"missing required key"}},
      {"dt_zero", "courant_number = 0.2", "dt = 0.0", "discretisation.dt", {"must be > 0 (got 0)"}},
      {"dt_negative",
       "courant_number = 0.2",
       "dt = -1e-4",
       "discretisation.dt",
       {"must be > 0 (got -0.0001)"}},
      {"h_zero",
       "support_radius_over_dr = 3.0",
       "support_radius_over_dr = 0.0",
       "discretisation.support_radius_over_dr",
       {"must be > 0 (got 0)"}},
      {"h_negative",
       "support_radius_over_dr = 3.0",
       "support_radius_over_dr = -3.0",
       "discretisation.support_radius_over_dr",
       {"must be > 0 (got -3)"}},
      {"dr_zero", "\ndr = 0.02", "\ndr = 0.0", "discretisation.dr", {"must be > 0 (got 0)"}},
      {"dr_negative",
       "\ndr = 0.02",
       "\ndr = -0.02",
       "discretisation.dr",
       {"must be > 0 (got -0.02)"}},
      {"fluid_block_outside_domain",
       "min = [0.0, 0.0]\nmax = [1.0, 2.0]",
       "min = [-1.0, 0.0]\nmax = [1.0, 2.0]",
       "particles[0]",
       {"outside the domain"}},
      {"container_outside_domain",
       "max = [4.1, 3.1]",
       "max = [4.0, 3.1]",
       "particles[1]",
       {"outside the domain"}},
      {"string_for_number",
       "sound_speed = 120.0",
       "sound_speed = \"120\"",
       "physics.sound_speed",
       {"expected a number, got a string"}},
      {"string_in_number_array",
       "max = [4.1, 3.1]",
       "max = [4.1, \"3.1\"]",
       "domain.max",
       {"expected an array of numbers"}},
      {"dimension_4",
       "dimension = 2",
       "dimension = 4",
       "dimension",
       {"must be 1, 2 or 3 for this model (got 4)"}},
      {"unknown_model",
       "model = \"wcsph\"",
       "model = \"isph\"",
       "model",
       {"unknown model \"isph\""}},
      {"unknown_particle_kind",
       "kind = \"fluid\"",
       "kind = \"sand\"",
       "particles[0].kind",
       {"unknown particle kind \"sand\""}},
      {"misspelt_lattice",
       "shape = \"box\"\nlattice = \"square\"",
       "shape = \"box\"\nlattice = \"hexagnal\"",
       "particles[0].lattice",
       {"expected \"square\", \"hexagonal\", \"bcc\" or \"vogel\", got \"hexagnal\""}},
      // A misspelt shape is named itself, not through a key that only a box needs.
      {"misspelt_shape",
       "shape = \"box\"\nlattice = \"square\"\nmin = [0.0, 0.0]\nmax = [1.0, 2.0]",
       "shape = \"sphere\"\nlattice = \"square\"\ncentre = [0.5, 1.0]\nradius = 0.5",
       "particles[0].shape",
       {"unknown shape \"sphere\"; expected one of \"box\", \"container\", \"annulus\", "
        "\"outline\", \"points\", \"stl\""}},
      {"capitalised_shape",
       "shape = \"box\"\nlattice = \"square\"\nmin = [0.0, 0.0]\nmax = [1.0, 2.0]",
       "shape = \"Points\"\nfile = \"water.csv\"",
       "particles[0].shape",
       {"unknown shape \"Points\""}},
      {"min_with_three_components",
       "min = [-0.1, -0.1]",
       "min = [-0.1, -0.1, -0.1]",
       "domain.min",
       {"expected 2 numbers, got 3"}},
      {"dt_and_courant_number",
       "courant_number = 0.2",
       "courant_number = 0.2\ndt = 1e-4",
       "discretisation.dt",
       {"not both"}},
      // Bad --set overrides on a good file.
      {"set_without_value",
       "",
       "",
       "discretisation.dr",
       {"--set expects key=value"},
       {"--set", "discretisation.dr"}},
      {"set_bad_index",
       "",
       "",
       "particles[x].min",
       {"expected an array index"},
       {"--set", "particles[x].min=[0.0, 0.0]"}},
      {"set_missing_element",
       "",
       "",
       "particles[7].min",
       {"no element 7"},
       {"--set", "particles[7].min=[0.0, 0.0]"}},
      {"set_negative_dr",
       "",
       "",
       "discretisation.dr",
       {"must be > 0 (got -0.01)"},
       {"--set", "discretisation.dr=-0.01"}},
      // The artificial viscosity (issue 33 item 5): alpha >= 0, and its explicit update within
      // its stable range at the case's dt (models/wcsph/parameters.cpp).
      {"negative_artificial_viscosity",
       "gravity = 9.8 ",
       "artificial_viscosity = -0.1\ngravity = 9.8 ",
       "physics.artificial_viscosity",
       {"must be a finite number >= 0 (0: off, the step stays reversible) (got -0.1)"}},
      {"artificial_viscosity_too_strong_for_the_step",
       "",
       "",
       "physics.artificial_viscosity",
       {"alpha c tau / h = 6 > 1 (tau = dt / 2 with step.splitting \"strang\", else dt",
        "the explicit update would amplify velocities"},
       {"--set", "physics.artificial_viscosity=30"}},
      {"set_word_for_number",
       "",
       "",
       "physics.sound_speed",
       {"expected a number, got a string"},
       {"--set", "physics.sound_speed=fast"}},
      {"set_unknown_key",
       "",
       "",
       "physics.sound_sped",
       {"unknown key (given with --set; every key: revsph cases --keys wcsph)"},
       {"--set", "physics.sound_sped=100"}},
  };
  return all;
}

class CliDefectTest : public ::testing::TestWithParam<Defect> {};

TEST_P(CliDefectTest, RunExitsWithOneLineAndWritesNothing) {
  const Defect& defect = GetParam();
  Sandbox sandbox;
  const std::string text = defect.from.empty()
                               ? dambreak_small_text()
                               : replaced_once(dambreak_small_text(), defect.from, defect.to);
  const fs::path case_path = sandbox.write_case(text);
  std::vector<std::string> arguments = {
      "run", case_path.string(), "--out", sandbox.out().string(), "--steps", "1"};
  arguments.insert(arguments.end(), defect.extra_arguments.begin(), defect.extra_arguments.end());
  const CommandResult result = sandbox.revsph(arguments);

  std::vector<std::string> parts;
  for (const std::string& part : defect.reason_parts) {
    parts.push_back(with_edit_line(part, text, defect.to));
  }
  // The file, then the key, exactly as CaseError formats them.
  parts.push_back(error_prefix + case_path.string() + ": " +
                  (defect.key.empty() ? std::string() : defect.key + ": "));
  expect_clean_rejection(sandbox, result, {"case.toml"}, parts);
}

INSTANTIATE_TEST_SUITE_P(BadCaseFiles, CliDefectTest, ::testing::ValuesIn(defects()),
                         [](const ::testing::TestParamInfo<Defect>& param_info) {
                           return param_info.param.name;
                         });

// ---------------------------------------------------------------------------------------------
// The other subcommands reject the same way.

// `revsph <command> CASE --steps 1`, CASE being dambreak-small with `from` replaced by `to`, is
// rejected; the message holds CASE followed by `after_path`, then each of `parts` (in both,
// "@LINE@" stands for the line of the edit).
void expect_command_rejects_edit(const std::string& command, const std::string& from,
                                 const std::string& to, const std::string& after_path,
                                 const std::vector<std::string>& parts = {}) {
  Sandbox sandbox;
  const std::string text = replaced_once(dambreak_small_text(), from, to);
  const fs::path case_path = sandbox.write_case(text);
  const CommandResult result = sandbox.revsph({command, case_path.string(), "--steps", "1"});
  std::vector<std::string> expected = {with_edit_line(case_path.string() + after_path, text, to)};
  for (const std::string& part : parts) {
    expected.push_back(with_edit_line(part, text, to));
  }
  expect_clean_rejection(sandbox, result, {"case.toml"}, expected);
}

TEST(CliBadInputTest, VerifyRejectsBadCase) {
  expect_command_rejects_edit("verify", "courant_number = 0.2", "dt = -1e-4",
                              ": discretisation.dt: ", {"must be > 0"});
}

TEST(CliBadInputTest, VerifyRejectsSyntaxError) {
  expect_command_rejects_edit("verify", "\ndr = 0.02", "\ndr = = 0.02",
                              ": syntax error at line @LINE@,");
}

TEST(CliBadInputTest, HashRejectsBadCase) {
  expect_command_rejects_edit("hash", "sound_speed = 120.0", "sound_speed = \"120\"",
                              ": physics.sound_speed: ", {"got a string"});
}

TEST(CliBadInputTest, HashRejectsUnknownKey) {
  expect_command_rejects_edit(
      "hash", "dimension = 2", "dimension = 2\ndimensions = 2",
      ": dimensions: ", {"unknown key (line @LINE@; every key: revsph cases --keys wcsph)"});
}

TEST(CliBadInputTest, MissingCaseFileIsRejected) {
  Sandbox sandbox;
  const fs::path case_path = sandbox.work() / "absent.toml";
  const CommandResult result =
      sandbox.revsph({"run", case_path.string(), "--out", sandbox.out().string(), "--steps", "1"});
  expect_clean_rejection(sandbox, result, {},
                         {case_path.string() + ": ", "no such file", "dambreak-small"});
}

TEST(CliBadInputTest, DirectoryAsCaseFileIsRejected) {
  Sandbox sandbox;
  const fs::path case_path = sandbox.work() / "cases";
  fs::create_directory(case_path);
  const CommandResult result =
      sandbox.revsph({"run", case_path.string(), "--out", sandbox.out().string(), "--steps", "1"});
  expect_clean_rejection(sandbox, result, {"cases"}, {case_path.string() + ": ", "is a directory"});
}

TEST(CliBadInputTest, EmptyCaseFileIsRejected) {
  Sandbox sandbox;
  const fs::path case_path = sandbox.write_case("");
  const CommandResult result =
      sandbox.revsph({"run", case_path.string(), "--out", sandbox.out().string(), "--steps", "1"});
  expect_clean_rejection(sandbox, result, {"case.toml"},
                         {case_path.string() + ": model: ", "missing required key"});
}

// ---------------------------------------------------------------------------------------------
// Options that are well formed but cannot be honoured.

TEST(CliBadInputTest, SnapshotGivenAsCaseSaysUseFrom) {
  Sandbox sandbox;
  const fs::path first = sandbox.work() / "first";
  const CommandResult made =
      sandbox.revsph({"run", "dambreak-small", "--steps", "0", "--out", first.string()});
  ASSERT_EQ(made.exit_status, 0) << made;
  const fs::path snapshot = first / "snapshots" / "step_000000000.h5";
  ASSERT_TRUE(fs::is_regular_file(snapshot)) << made;
  for (const std::string command : {"run", "verify"}) {
    const CommandResult result = sandbox.revsph(
        {command, snapshot.string(), "--steps", "1", "--out", sandbox.out().string()});
    expect_clean_rejection(sandbox, result, {"first"},
                           {error_prefix + snapshot.string() + ": this is a snapshot: use --from"});
  }
}

TEST(CliBadInputTest, FloatArithmeticOnAFixedPointOnlyModelIsBadInput) {
  Sandbox sandbox;
  for (const std::string command : {"run", "verify"}) {
    const CommandResult result =
        sandbox.revsph({command, "cavity-re100-small", "--arithmetic", "float", "--steps", "1",
                        "--out", sandbox.out().string()});
    expect_clean_rejection(sandbox, result, {},
                           {"cavity-re100-small.toml: --arithmetic: ", "fixed point only"});
  }
}

// An --out that cannot be created is bad input, found before the set-up (nothing on stdout: not
// even the run's header line), not a filesystem error after it (exit 3 before issue 33's fix).
TEST(CliBadInputTest, OutputDirectoryThatCannotBeCreatedIsRefusedBeforeSetUp) {
  Sandbox sandbox;
  const fs::path blocker = sandbox.work() / "blocker";
  std::ofstream(blocker) << "a file, not a directory\n";
  const fs::path out = blocker / "run";
  const CommandResult result =
      sandbox.revsph({"run", "dambreak-small", "--steps", "1", "--out", out.string()});
  expect_clean_rejection(sandbox, result, {"blocker"},
                         {"dambreak-small: --out: ", out.string() + " cannot be created: ",
                          blocker.string() + " is not a directory"});
}

// Where the permissions allow it but the file system does not (root in /proc; a read-only
// mount): still bad input before the set-up (exit 3 after it before the fix).
TEST(CliBadInputTest, OutputDirectoryOnAFileSystemThatRefusesItIsRefusedBeforeSetUp) {
  Sandbox sandbox;
  const fs::path out = "/proc/revsph-out/run";
  const CommandResult result =
      sandbox.revsph({"run", "dambreak-small", "--steps", "1", "--out", out.string()});
  expect_clean_rejection(sandbox, result, {},
                         {"dambreak-small: --out: ", out.string() + " cannot be created: "});
}

TEST(CliBadInputTest, ZeroThreadsIsRefusedInOneLine) {
  Sandbox sandbox;
  for (const std::string threads : {"0", "-2"}) {
    const CommandResult result = sandbox.revsph(
        {"run", "--threads", threads, "--steps", "1", "--out", sandbox.out().string()});
    expect_clean_rejection(sandbox, result, {},
                           {error_prefix + "--threads: must be at least 1 (got " + threads + ")"});
  }
}

TEST(CliBadInputTest, EndBeforeTheFirstStepIsRefused) {
  Sandbox sandbox;
  for (const std::string command : {"run", "verify", "hash"}) {
    std::vector<std::string> arguments = {command, "dambreak-small", "--t-end", "1e-7"};
    if (command != "hash") {
      arguments.insert(arguments.end(), {"--out", sandbox.out().string()});
    }
    const CommandResult result = sandbox.revsph(arguments);
    expect_clean_rejection(
        sandbox, result, {},
        {error_prefix +
         "dambreak-small.toml: --t-end: shorter than one time step (1e-07 s < dt = "});
  }
}

// ---------------------------------------------------------------------------------------------
// A valid run, and the guard on an existing output directory.

TEST(CliRunTest, ValidCaseRunsAndWritesOutput) {
  Sandbox sandbox;
  const fs::path case_path = sandbox.write_case(dambreak_small_text());
  const CommandResult result =
      sandbox.revsph({"run", case_path.string(), "--out", sandbox.out().string(), "--steps", "1"});
  EXPECT_EQ(result.exit_status, 0) << result;
  EXPECT_EQ(result.err, "") << result;
  EXPECT_NE(result.out.find("state hash: "), std::string::npos) << result;
  EXPECT_TRUE(fs::is_regular_file(sandbox.out() / "energy.csv")) << result;
  EXPECT_TRUE(fs::is_regular_file(sandbox.out() / "summary.json")) << result;
  EXPECT_EQ(entries_of(sandbox.work()), (std::set<std::string>{"case.toml", "out"}));
}

TEST(CliRunTest, NonEmptyOutputDirectoryNeedsForce) {
  Sandbox sandbox;
  const fs::path case_path = sandbox.write_case(dambreak_small_text());
  fs::create_directory(sandbox.out());
  const fs::path earlier = sandbox.out() / "earlier-result.txt";
  std::ofstream(earlier) << "keep me\n";

  const CommandResult refused =
      sandbox.revsph({"run", case_path.string(), "--out", sandbox.out().string(), "--steps", "1"});
  EXPECT_EQ(refused.exit_status, 2) << refused;
  EXPECT_EQ(refused.out, "") << refused;
  EXPECT_EQ(refused.err.rfind(error_prefix + case_path.string() + ": --out: ", 0), 0u) << refused;
  EXPECT_EQ(refused.err.find('\n'), refused.err.size() - 1) << refused;
  EXPECT_NE(refused.err.find("--force"), std::string::npos) << refused;
  EXPECT_EQ(entries_of(sandbox.out()), (std::set<std::string>{"earlier-result.txt"}));
  EXPECT_EQ(read_file(earlier), "keep me\n");

  const CommandResult forced = sandbox.revsph(
      {"run", case_path.string(), "--out", sandbox.out().string(), "--steps", "1", "--force"});
  EXPECT_EQ(forced.exit_status, 0) << forced;
  EXPECT_EQ(forced.err, "") << forced;
  EXPECT_TRUE(fs::is_regular_file(sandbox.out() / "energy.csv")) << forced;
  EXPECT_TRUE(fs::is_regular_file(sandbox.out() / "summary.json")) << forced;
}

TEST(CliRunTest, EmptyOutputDirectoryIsUsedWithoutForce) {
  Sandbox sandbox;
  const fs::path case_path = sandbox.write_case(dambreak_small_text());
  fs::create_directory(sandbox.out());
  const CommandResult result =
      sandbox.revsph({"run", case_path.string(), "--out", sandbox.out().string(), "--steps", "1"});
  EXPECT_EQ(result.exit_status, 0) << result;
  EXPECT_TRUE(fs::is_regular_file(sandbox.out() / "summary.json")) << result;
}

} // namespace
