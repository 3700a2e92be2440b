// Bad case files are rejected with one CaseError that names the file, the key and the reason.
//
// Each defect is the built-in dambreak-small case with one edit, read through the same sequence
// as the command line (tools/revsph/common.cpp: read_run_settings, create_simulation,
// require_no_unknown_keys), so a defect that only the CLI's order of reading would catch, or
// miss, shows up here too.

#include "core/case_file.hpp"
#include "core/model_registry.hpp"
#include "core/particle_blocks.hpp"
#include "core/run_settings.hpp"

#include "case_text.hpp"
#include "temp_directory.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

namespace revsph {
namespace {

const std::string bad_file_name = "bad.toml";

std::string dambreak_small_text() {
  return testing::builtin_case_text("dambreak-small");
}

using testing::line_at;
using testing::replaced_once;

// What tools/revsph/common.cpp does with a case after loading and overriding it.
void read_like_the_cli(const CaseFile& case_file) {
  read_run_settings(case_file);
  create_simulation(case_file, SimulationOptions{});
  case_file.require_no_unknown_keys();
}

struct Override {
  std::string key;
  std::string value;
};

// The CaseError that reading `text` raises, or nothing if the case is accepted. Any other
// exception escapes and fails the test: a bad case must never surface as anything else.
std::optional<CaseError> case_error(const std::string& text,
                                    const std::vector<Override>& overrides = {}) {
  try {
    CaseFile case_file = CaseFile::parse(text, bad_file_name);
    for (const Override& o : overrides) {
      case_file.set(o.key, o.value);
    }
    read_like_the_cli(case_file);
  } catch (const CaseError& error) {
    return error;
  }
  return std::nullopt;
}

void expect_one_line_message(const CaseError& error) {
  const std::string message = error.what();
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  const std::string expected_prefix =
      error.file() + ": " + (error.key().empty() ? std::string() : error.key() + ": ");
  EXPECT_EQ(message.rfind(expected_prefix, 0), 0u) << message;
  EXPECT_NE(message.find(error.reason()), std::string::npos) << message;
}

// ---------------------------------------------------------------------------------------------
// One edit of the built-in case per defect.

struct Defect {
  std::string name; // test-name suffix
  std::string from; // text of the built-in case to replace (must occur once)
  std::string to;
  std::string key; // expected CaseError::key(), exactly
  // Expected parts of CaseError::reason(). "@LINE@" stands for the line on which the last line
  // of `to` ends up, for messages that point into the file.
  std::vector<std::string> reason_parts;
};

std::ostream& operator<<(std::ostream& out, const Defect& defect) {
  return out << defect.name;
}

const std::vector<Defect>& defects() {
  static const std::vector<Defect> all = {
      // Syntax errors: no key, the line in the reason.
      {"syntax_error_double_equals",
       "\ndr = 0.02",
       "\ndr = = 0.02",
       "",
       {"syntax error at line @LINE@,"}},
      {"syntax_error_unterminated_string",
       "name = \"dambreak-small\"",
       "name = \"dambreak-small",
       "",
       {"syntax error at line @LINE@,"}},
      {"syntax_error_duplicate_key",
       "\ndr = 0.02",
       "\ndr = 0.02\ndr = 0.03",
       "",
       {"syntax error at line @LINE@,", "dr"}},
      {"syntax_error_unclosed_table_header",
       "[wall]",
       "[wall",
       "",
       {"syntax error at line @LINE@,"}},
      // Unknown keys.
      {"unknown_key",
       "\ndr = 0.02",
       "\ndr = 0.02\ndrr = 0.02",
       "discretisation.drr",
       {"unknown key", "line @LINE@; every key: revsph cases --keys wcsph)"}},
      {"unknown_key_top_level",
       "dimension = 2",
       "dimension = 2\ndimensions = 2",
       "dimensions",
       {"unknown key", "line @LINE@; every key: revsph cases --keys wcsph)"}},
      {"misspelt_table_name",
       "[wall]\nradius_over_dr = 0.95",
       "[walls]\nradius_over_dr = 0.95",
       "walls.radius_over_dr",
       {"unknown key", "line @LINE@; every key: revsph cases --keys wcsph)"}},
      {"unknown_key_in_particles_block",
       "kind = \"fluid\"",
       "kind = \"fluid\"\ncolour = \"blue\"",
       "particles[0].colour",
       {"unknown key", "line @LINE@; every key: revsph cases --keys wcsph)"}},
      {"unknown_key_in_run",
       "t_end = 1.0",
       "t_end = 1.0\nstep = 10",
       "run.step",
       {"unknown key", "line @LINE@; every key: revsph cases --keys wcsph)"}},
      {"unknown_empty_table", "[run]", "[runs]\n[run]", "runs", {"unknown key"}},
      // Missing required keys.
      {"missing_model", "model = \"wcsph\"", "", "model", {"missing required key"}},
      {"missing_dimension", "dimension = 2", "", "dimension", {"missing required key"}},
      {"missing_sound_speed",
       "sound_speed = 120.0",
       "",
       "physics.sound_speed",
       {"missing required key"}},
      {"missing_dr", "\ndr = 0.02", "", "discretisation.dr", {"missing required key"}},
      {"missing_dt_and_courant_number",
       "courant_number = 0.2",
       "",
       "discretisation.dt",
       {"missing required key", "courant_number"}},
      {"missing_domain_max", "max = [4.1, 3.1]", "", "domain.max", {"missing required key"}},
      {"missing_particle_kind",
       "kind = \"wall\"",
       "",
       "particles[1].kind",
       {"missing required key"}},
      {"missing_particle_min",
       "lattice = \"square\"\nmin = [0.0, 0.0]\nmax = [1.0, 2.0]",
       "lattice = \"square\"\nmax = [1.0, 2.0]",
       "particles[0].min",
       {"missing required key"}},
      // dt, h and dr must be > 0.
      {"dt_zero",
       "courant_number = 0.2",
       "dt = 0.0",
       "discretisation.dt",
       {"must be > 0", "got 0"}},
      {"dt_negative",
       "courant_number = 0.2",
       "dt = -1e-4",
       "discretisation.dt",
       {"must be > 0", "got -0.0001"}},
      {"dt_zero_integer",
       "courant_number = 0.2",
       "dt = 0",
       "discretisation.dt",
       {"must be > 0", "got 0"}},
      {"courant_number_zero",
       "courant_number = 0.2",
       "courant_number = 0.0",
       "discretisation.courant_number",
       {"must be > 0", "got 0"}},
      {"h_zero",
       "support_radius_over_dr = 3.0",
       "support_radius_over_dr = 0.0",
       "discretisation.support_radius_over_dr",
       {"must be > 0", "got 0"}},
      {"h_negative",
       "support_radius_over_dr = 3.0",
       "support_radius_over_dr = -3.0",
       "discretisation.support_radius_over_dr",
       {"must be > 0", "got -3"}},
      {"dr_zero", "\ndr = 0.02", "\ndr = 0.0", "discretisation.dr", {"must be > 0", "got 0"}},
      {"dr_negative",
       "\ndr = 0.02",
       "\ndr = -0.02",
       "discretisation.dr",
       {"must be > 0", "got -0.02"}},
      {"dr_not_a_number",
       "\ndr = 0.02",
       "\ndr = nan",
       "discretisation.dr",
       {"expected a finite number", "nan"}},
      {"dr_infinite",
       "\ndr = 0.02",
       "\ndr = inf",
       "discretisation.dr",
       {"expected a finite number", "inf"}},
      {"particle_spacing_zero",
       "layers = 1",
       "layers = 1\nspacing = 0.0",
       "particles[1].spacing",
       {"must be > 0"}},
      // Particle blocks outside the domain.
      {"fluid_block_outside_domain",
       "min = [0.0, 0.0]\nmax = [1.0, 2.0]",
       "min = [-1.0, 0.0]\nmax = [1.0, 2.0]",
       "particles[0]",
       {"outside the domain", "[domain]"}},
      {"container_outside_domain",
       "max = [4.1, 3.1]",
       "max = [4.0, 3.1]",
       "particles[1]",
       {"outside the domain"}},
      {"domain_inverted",
       "max = [4.1, 3.1]",
       "max = [-4.1, 3.1]",
       "domain.max",
       {"must be greater than domain.min"}},
      {"block_inverted",
       "max = [1.0, 2.0]",
       "max = [-1.0, 2.0]",
       "particles[0].max",
       {"must be greater than min"}},
      {"block_thinner_than_spacing",
       "max = [1.0, 2.0]",
       "max = [0.01, 2.0]",
       "particles[0]",
       {"holds no particles"}},
      // A string (or another type) where a number belongs.
      {"string_for_number",
       "sound_speed = 120.0",
       "sound_speed = \"120\"",
       "physics.sound_speed",
       {"expected a number", "got a string"}},
      {"string_for_dr",
       "\ndr = 0.02",
       "\ndr = \"0.02\"",
       "discretisation.dr",
       {"expected a number", "got a string"}},
      {"string_in_number_array",
       "max = [4.1, 3.1]",
       "max = [4.1, \"3.1\"]",
       "domain.max",
       {"expected an array of numbers", "a string"}},
      {"number_for_array",
       "max = [4.1, 3.1]",
       "max = 4.1",
       "domain.max",
       {"expected an array of 2 numbers", "got a number"}},
      {"string_for_integer",
       "dimension = 2",
       "dimension = \"2\"",
       "dimension",
       {"expected an integer", "got a string"}},
      {"fraction_for_integer",
       "dimension = 2",
       "dimension = 2.5",
       "dimension",
       {"expected an integer", "got a number"}},
      {"number_for_string",
       "model = \"wcsph\"",
       "model = 1",
       "model",
       {"expected a string", "got an integer"}},
      {"boolean_for_number",
       "gravity = 9.8",
       "gravity = true",
       "physics.gravity",
       {"expected a number", "got a boolean"}},
      // Values outside what the model knows.
      {"dimension_4",
       "dimension = 2",
       "dimension = 4",
       "dimension",
       {"must be 1, 2 or 3", "got 4"}},
      {"unknown_model",
       "model = \"wcsph\"",
       "model = \"isph\"",
       "model",
       {"unknown model \"isph\"", "wcsph"}},
      {"unknown_particle_kind",
       "kind = \"fluid\"",
       "kind = \"sand\"",
       "particles[0].kind",
       {"unknown particle kind \"sand\"", "\"fluid\"", "\"wall\""}},
      {"misspelt_lattice",
       "shape = \"box\"\nlattice = \"square\"",
       "shape = \"box\"\nlattice = \"hexagnal\"",
       "particles[0].lattice",
       {"\"square\", \"hexagonal\", \"bcc\" or \"vogel\"", "hexagnal"}},
      {"unknown_shape",
       "shape = \"box\"",
       "shape = \"sphere\"",
       "particles[0].shape",
       {"unknown shape \"sphere\"; expected one of \"box\", \"container\", \"annulus\", "
        "\"outline\", \"points\", \"stl\""}},
      {"layers_on_a_box",
       "max = [1.0, 2.0]",
       "max = [1.0, 2.0]\nlayers = 2",
       "particles[0].layers",
       {"only a \"container\""}},
      {"container_layers_zero",
       "layers = 1",
       "layers = 0",
       "particles[1].layers",
       {"between 1 and 1000", "got 0"}},
      {"block_min_three_components",
       "max = [1.0, 2.0]",
       "max = [1.0, 2.0, 0.5]",
       "particles[0].max",
       {"expected 2 numbers, got 3"}},
      {"domain_min_one_component",
       "min = [-0.1, -0.1]",
       "min = [-0.1]",
       "domain.min",
       {"expected 2 numbers, got 1"}},
      {"dimension_3_with_2d_vectors",
       "dimension = 2",
       "dimension = 3",
       "domain.min",
       {"expected 3 numbers, got 2"}},
      {"dt_and_courant_number",
       "courant_number = 0.2",
       "courant_number = 0.2\ndt = 1e-4",
       "discretisation.dt",
       {"either dt or courant_number, not both"}},
      {"steps_and_t_end",
       "t_end = 1.0",
       "t_end = 1.0\nsteps = 10",
       "run.t_end",
       {"either run.steps or run.t_end, not both"}},
      {"t_end_zero", "t_end = 1.0", "t_end = 0.0", "run.t_end", {"must be > 0"}},
      {"energy_every_zero",
       "energy_every = 100",
       "energy_every = 0",
       "output.energy_every",
       {"must be >= 1"}},
      // Blocks from files (issue 33): a missing point file, lattice keys on a points block, an
      // STL block in 2D; snapshots in simulated seconds.
      {"points_file_missing",
       "shape = \"box\"\nlattice = \"square\"\nmin = [0.0, 0.0]\nmax = [1.0, 2.0]",
       "shape = \"points\"\nfile = \"no-such-points.csv\"",
       "particles[0].file",
       {"no-such-points.csv: no such file"}},
      {"points_with_a_lattice",
       "shape = \"box\"",
       "shape = \"points\"\nfile = \"fluid.csv\"",
       "particles[0].lattice",
       {"a \"points\" block's particles come from its file"}},
      {"stl_in_2d",
       "shape = \"box\"",
       "shape = \"stl\"\nfile = \"obstacle.stl\"",
       "particles[0].shape",
       {"an \"stl\" block is three-dimensional"}},
      // Periodic boundaries: an axis the case does not have, an axis named twice.
      {"periodic_axis_beyond_the_dimension",
       "max = [4.1, 3.1]",
       "max = [4.1, 3.1]\nperiodic = \"xz\"",
       "domain.periodic",
       {"names the axes that are periodic"}},
      {"periodic_axis_twice",
       "max = [4.1, 3.1]",
       "max = [4.1, 3.1]\nperiodic = \"xx\"",
       "domain.periodic",
       {"names axis x twice"}},
      {"snapshot_interval_negative",
       "energy_every = 100",
       "energy_every = 100\nsnapshot_interval = -1.0",
       "output.snapshot_interval",
       {"must be > 0"}},
      {"cell_size_factor_below_one",
       "courant_number = 0.2",
       "courant_number = 0.2\ncell_size_factor = 0.5",
       "discretisation.cell_size_factor",
       {"between 1 and 100"}},
  };
  return all;
}

class CaseDefectTest : public ::testing::TestWithParam<Defect> {};

TEST_P(CaseDefectTest, RejectedWithFileKeyAndReason) {
  const Defect& defect = GetParam();
  const std::string text = replaced_once(dambreak_small_text(), defect.from, defect.to);
  const std::optional<CaseError> error = case_error(text);
  ASSERT_TRUE(error.has_value()) << "the defective case was accepted:\n" << text;
  EXPECT_EQ(error->file(), bad_file_name);
  EXPECT_EQ(error->key(), defect.key) << error->what();
  for (const std::string& part : defect.reason_parts) {
    const std::string expected = testing::with_edit_line(part, text, defect.to);
    EXPECT_NE(error->reason().find(expected), std::string::npos)
        << "reason \"" << error->reason() << "\" lacks \"" << expected << "\"";
  }
  expect_one_line_message(*error);
}

INSTANTIATE_TEST_SUITE_P(BadCaseFiles, CaseDefectTest, ::testing::ValuesIn(defects()),
                         [](const ::testing::TestParamInfo<Defect>& param_info) {
                           return param_info.param.name;
                         });

TEST(CaseFileTest, BuiltinCaseIsAccepted) {
  EXPECT_FALSE(case_error(dambreak_small_text()).has_value());
}

TEST(CaseFileTest, SyntaxErrorOnFirstLineGivesLineAndColumn) {
  const std::optional<CaseError> error = case_error("model = \n" + dambreak_small_text());
  ASSERT_TRUE(error.has_value());
  EXPECT_EQ(error->file(), bad_file_name);
  EXPECT_EQ(error->key(), "");
  EXPECT_EQ(error->reason().rfind("syntax error at line 1, column ", 0), 0u) << error->reason();
  expect_one_line_message(*error);
}

TEST(CaseFileTest, SyntaxErrorIsRaisedByParseItself) {
  try {
    CaseFile::parse("a = [1, 2", "broken.toml");
    FAIL() << "a syntax error was accepted";
  } catch (const CaseError& error) {
    EXPECT_EQ(error.file(), "broken.toml");
    EXPECT_EQ(error.key(), "");
    EXPECT_NE(error.reason().find("syntax error at line 1"), std::string::npos) << error.reason();
  }
}

TEST(CaseFileTest, MessageIsFileKeyReason) {
  const CaseError with_key("c.toml", "discretisation.dr", "must be > 0 (got 0)");
  EXPECT_STREQ(with_key.what(), "c.toml: discretisation.dr: must be > 0 (got 0)");
  const CaseError without_key("c.toml", "", "syntax error at line 3, column 1: x");
  EXPECT_STREQ(without_key.what(), "c.toml: syntax error at line 3, column 1: x");
}

TEST(CaseFileTest, FirstUnknownKeyInFileOrderIsReported) {
  // Both are unknown; the one higher up in the file is named, whatever order keys are read in.
  std::string text = replaced_once(dambreak_small_text(), "energy_every = 100",
                                   "energy_every = 100\nlast_unknown = 1");
  text = replaced_once(text, "dimension = 2", "dimension = 2\nfirst_unknown = 1");
  const std::optional<CaseError> error = case_error(text);
  ASSERT_TRUE(error.has_value());
  EXPECT_EQ(error->key(), "first_unknown");
  EXPECT_NE(
      error->reason().find("line " + std::to_string(line_at(text, text.find("first_"))) + ";"),
      std::string::npos)
      << error->reason();
}

TEST(CaseFileTest, OnlyOneErrorForSeveralDefects) {
  // Reading stops at the first defect: one message, not a list.
  std::string text = replaced_once(dambreak_small_text(), "\ndr = 0.02", "\ndr = -0.02");
  text = replaced_once(text, "sound_speed = 120.0", "sound_speed = \"fast\"");
  const std::optional<CaseError> error = case_error(text);
  ASSERT_TRUE(error.has_value());
  EXPECT_EQ(error->key(), "physics.sound_speed");
  expect_one_line_message(*error);
}

// ---------------------------------------------------------------------------------------------
// Command-line overrides (--set) go through CaseFile::set.

TEST(CaseFileOverrideTest, ValidOverrideIsAcceptedAndRecorded) {
  CaseFile case_file = CaseFile::parse(dambreak_small_text(), bad_file_name);
  case_file.set("discretisation.dr", "0.04");
  case_file.set("particles[0].lattice", "hexagonal"); // a bare word is taken as a string
  EXPECT_NO_THROW(read_like_the_cli(case_file));
  EXPECT_DOUBLE_EQ(case_file.number("discretisation.dr"), 0.04);
  EXPECT_EQ(case_file.string("particles[0].lattice"), "hexagonal");
  ASSERT_EQ(case_file.overrides().size(), 2u);
  EXPECT_EQ(case_file.overrides()[0], "discretisation.dr=0.04");
  EXPECT_EQ(case_file.text(), dambreak_small_text()) << "the text stays as written";
}

TEST(CaseFileOverrideTest, OverriddenValueIsValidatedLikeTheFile) {
  const std::optional<CaseError> negative =
      case_error(dambreak_small_text(), {{"discretisation.dr", "-0.01"}});
  ASSERT_TRUE(negative.has_value());
  EXPECT_EQ(negative->key(), "discretisation.dr");
  EXPECT_NE(negative->reason().find("must be > 0"), std::string::npos);

  const std::optional<CaseError> word =
      case_error(dambreak_small_text(), {{"physics.sound_speed", "fast"}});
  ASSERT_TRUE(word.has_value());
  EXPECT_EQ(word->key(), "physics.sound_speed");
  EXPECT_NE(word->reason().find("expected a number, got a string"), std::string::npos);
}

TEST(CaseFileOverrideTest, UnknownKeyFromOverrideSaysSo) {
  const std::optional<CaseError> error =
      case_error(dambreak_small_text(), {{"physics.sound_sped", "100"}});
  ASSERT_TRUE(error.has_value());
  EXPECT_EQ(error->key(), "physics.sound_sped");
  EXPECT_NE(
      error->reason().find("unknown key (given with --set; every key: revsph cases --keys wcsph)"),
      std::string::npos)
      << error->reason();
}

struct BadOverride {
  std::string name;
  std::string key;
  std::string reason_part;
};

std::ostream& operator<<(std::ostream& out, const BadOverride& o) {
  return out << o.name;
}

class BadOverrideTest : public ::testing::TestWithParam<BadOverride> {};

TEST_P(BadOverrideTest, RejectedWithTheKey) {
  const BadOverride& bad = GetParam();
  CaseFile case_file = CaseFile::parse(dambreak_small_text(), bad_file_name);
  try {
    case_file.set(bad.key, "1.0");
    FAIL() << "--set " << bad.key << "=1.0 was accepted";
  } catch (const CaseError& error) {
    EXPECT_EQ(error.file(), bad_file_name);
    EXPECT_EQ(error.key(), bad.key);
    EXPECT_NE(error.reason().find(bad.reason_part), std::string::npos) << error.reason();
    expect_one_line_message(error);
  }
}

INSTANTIATE_TEST_SUITE_P(
    BadOverrides, BadOverrideTest,
    ::testing::Values(
        BadOverride{"index_not_a_number", "particles[x].min", "expected an array index"},
        BadOverride{"index_too_large", "particles[99999999999999999999999].min",
                    "expected an array index"},
        BadOverride{"index_unclosed", "particles[0.min", "expected an array index"},
        BadOverride{"index_empty", "particles[].min", "expected an array index"},
        BadOverride{"no_such_element", "particles[7].min", "no element 7 in 'particles'"},
        BadOverride{"index_into_a_table", "physics[0].gravity", "no element 0 in 'physics'"},
        BadOverride{"whole_element", "particles[0]", "cannot replace a whole array element"},
        BadOverride{"through_a_value", "model.name", "'model' is not a table"},
        BadOverride{"through_an_element_value", "particles[0].kind.x",
                    "'particles[0].kind' is not a table"},
        BadOverride{"empty_part", "physics..gravity", "empty part"},
        BadOverride{"leading_dot", ".gravity", "empty part"},
        BadOverride{"trailing_dot", "physics.", "empty part"}),
    [](const ::testing::TestParamInfo<BadOverride>& param_info) { return param_info.param.name; });

// ---------------------------------------------------------------------------------------------
// Loading from disk.

using testing::TempDirectory;

TEST(CaseFileLoadTest, FileNameIsTheSourceName) {
  TempDirectory dir;
  const std::filesystem::path file = dir.path() / "case.toml";
  std::ofstream(file) << replaced_once(dambreak_small_text(), "\ndr = 0.02", "\ndr = 0");
  try {
    read_like_the_cli(CaseFile::load(file));
    FAIL() << "\ndr = 0 was accepted";
  } catch (const CaseError& error) {
    EXPECT_EQ(error.file(), file.string());
    EXPECT_EQ(error.key(), "discretisation.dr");
  }
}

TEST(CaseFileLoadTest, MissingFileIsACaseError) {
  TempDirectory dir;
  const std::filesystem::path file = dir.path() / "absent.toml";
  try {
    CaseFile::load(file);
    FAIL() << "a missing file was loaded";
  } catch (const CaseError& error) {
    EXPECT_EQ(error.file(), file.string());
    EXPECT_EQ(error.key(), "");
    EXPECT_NE(error.reason().find("cannot open"), std::string::npos) << error.reason();
  }
}

TEST(CaseFileLoadTest, DirectoryIsNotACase) {
  TempDirectory dir;
  try {
    CaseFile::load(dir.path());
    FAIL() << "a directory was loaded as a case";
  } catch (const CaseError& error) {
    EXPECT_EQ(error.file(), dir.path().string());
    EXPECT_NE(error.reason().find("is a directory"), std::string::npos) << error.reason();
  }
}

TEST(CaseFileLoadTest, UnknownNameIsNeitherFileNorBuiltin) {
  try {
    load_case("/nonexistent/no-such-case.toml");
    FAIL() << "an unknown case was loaded";
  } catch (const CaseError& error) {
    EXPECT_EQ(error.file(), "/nonexistent/no-such-case.toml");
    EXPECT_NE(error.reason().find("no such file"), std::string::npos) << error.reason();
    EXPECT_NE(error.reason().find("dambreak-small"), std::string::npos) << error.reason();
  }
}

TEST(CaseFileLoadTest, BuiltinNameLoads) {
  const CaseFile case_file = load_case("dambreak-small");
  EXPECT_EQ(case_file.source_name(), "dambreak-small.toml");
  EXPECT_NO_THROW(read_like_the_cli(case_file));
}

// ---------------------------------------------------------------------------------------------
// read_domain and read_particle_blocks on their own, with a minimal case.

constexpr std::string_view test_kinds[] = {"fluid", "wall"};
const ParticleBudget test_budget{400.0, std::size_t{1} << 30};

std::string minimal_blocks_case(const std::string& particles) {
  return "[domain]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n\n" + particles;
}

template <class Check>
void expect_block_error(const std::string& particles, const std::string& key,
                        const std::string& reason_part, Check read) {
  const CaseFile case_file = CaseFile::parse(minimal_blocks_case(particles), "blocks.toml");
  try {
    read(case_file);
    FAIL() << "accepted:\n" << particles;
  } catch (const CaseError& error) {
    EXPECT_EQ(error.file(), "blocks.toml");
    EXPECT_EQ(error.key(), key) << error.what();
    EXPECT_NE(error.reason().find(reason_part), std::string::npos) << error.reason();
  }
}

void read_blocks_2d(const CaseFile& case_file) {
  read_particle_blocks<2>(case_file, 0.1, read_domain<2>(case_file), test_kinds, test_budget);
}

TEST(ParticleBlocksTest, BlockInsideDomainIsRead) {
  const CaseFile case_file = CaseFile::parse(
      minimal_blocks_case("[[particles]]\nkind = \"fluid\"\nmin = [0.0, 0.0]\nmax = [0.5, 0.5]\n"),
      "blocks.toml");
  const Box<2> domain = read_domain<2>(case_file);
  const auto blocks = read_particle_blocks<2>(case_file, 0.1, domain, test_kinds, test_budget);
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_EQ(blocks[0].key, "particles[0]");
  EXPECT_EQ(blocks[0].kind, "fluid");
  EXPECT_EQ(blocks[0].positions.size(), 25u);
  EXPECT_NO_THROW(case_file.require_no_unknown_keys());
}

// A block packed far below dr gives each of its particles (dr / spacing)^D times the neighbours
// the budget's per-particle figure assumed at dr (here 2 kB of the 2.4 kB). 625 x 625 particles at
// spacing dr / 62.5 fit a 1 GB budget by their count alone (0.94 GB) but would need about 3 TB
// with their neighbours: refused. 250 x 250 at dr / 25 (the fuzz test's hang: a dummy block at
// spacing 4e-3 with dr = 0.1): 150 MB by count, 78 GB with neighbours.
TEST(ParticleBlocksTest, DenseBlockIsRefusedForItsNeighbours) {
  const ParticleBudget budget{2400.0, std::size_t{1} << 30, 2000.0};
  const auto read = [&](const CaseFile& case_file) {
    read_particle_blocks<2>(case_file, 0.1, read_domain<2>(case_file), test_kinds, budget);
  };
  expect_block_error(
      "[[particles]]\nkind = \"fluid\"\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\nspacing = 0.0016\n",
      "particles", "of memory", read);
  const CaseFile wide = CaseFile::parse(
      minimal_blocks_case(
          "[[particles]]\nkind = \"fluid\"\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\nspacing = 0.004\n"),
      "blocks.toml");
  const ParticleBudget no_neighbours{2400.0, std::size_t{1} << 30};
  EXPECT_NO_THROW(
      read_particle_blocks<2>(wide, 0.1, read_domain<2>(wide), test_kinds, no_neighbours));
  EXPECT_THROW(read(wide), CaseError);
}

TEST(ParticleBlocksTest, BlockOutsideDomainNamesTheBlock) {
  expect_block_error("[[particles]]\nkind = \"fluid\"\nmin = [0.0, 0.0]\nmax = [0.5, 0.5]\n"
                     "[[particles]]\nkind = \"wall\"\nmin = [0.5, 0.5]\nmax = [1.5, 1.0]\n",
                     "particles[1]", "outside the domain", read_blocks_2d);
}

TEST(ParticleBlocksTest, HugeThinVogelBoxIsRefusedBeforeGenerating) {
  // Found by the case fuzzer: a Vogel spiral walks its box's whole diagonal, so a box 100 m wide
  // and 4e-12 m high (no particles by area) took minutes before it was found to hold none.
  expect_block_error("[[particles]]\nkind = \"fluid\"\nlattice = \"vogel\"\n"
                     "min = [0.0, 0.0]\nmax = [1e2, 4.3e-12]\nspacing = 1e-3\n",
                     "particles[0]", "its max on axis 0", read_blocks_2d);
}

TEST(ParticleBlocksTest, ContainerWallsOutsideDomainNameTheBlock) {
  // The box itself fits the domain, its wall layers do not.
  expect_block_error("[[particles]]\nkind = \"wall\"\nshape = \"container\"\n"
                     "min = [0.0, 0.0]\nmax = [1.0, 1.0]\n",
                     "particles[0]", "outside the domain", read_blocks_2d);
}

TEST(ParticleBlocksTest, NoBlocksIsAnError) {
  expect_block_error("", "particles", "no [[particles]] blocks", read_blocks_2d);
}

TEST(ParticleBlocksTest, UnknownKindNamesTheAllowedKinds) {
  expect_block_error("[[particles]]\nkind = \"gas\"\nmin = [0.0, 0.0]\nmax = [0.5, 0.5]\n",
                     "particles[0].kind", "(this model has \"fluid\", \"wall\")", read_blocks_2d);
}

TEST(ParticleBlocksTest, NegativeSpacingIsAnError) {
  expect_block_error(
      "[[particles]]\nkind = \"fluid\"\nspacing = -0.1\nmin = [0.0, 0.0]\nmax = [0.5, 0.5]\n",
      "particles[0].spacing", "must be > 0", read_blocks_2d);
}

TEST(ParticleBlocksTest, StringCornerIsAnError) {
  expect_block_error("[[particles]]\nkind = \"fluid\"\nmin = \"origin\"\nmax = [0.5, 0.5]\n",
                     "particles[0].min", "got a string", read_blocks_2d);
}

TEST(ParticleBlocksTest, OpenTopOnABoxIsAnError) {
  expect_block_error(
      "[[particles]]\nkind = \"fluid\"\nopen_top = true\nmin = [0.0, 0.0]\nmax = [0.5, 0.5]\n",
      "particles[0].open_top", "only a \"container\"", read_blocks_2d);
}

TEST(ParticleBlocksTest, TooManyLayersIsAnError) {
  expect_block_error("[[particles]]\nkind = \"wall\"\nshape = \"container\"\nlayers = 1001\n"
                     "min = [0.2, 0.2]\nmax = [0.8, 0.8]\n",
                     "particles[0].layers", "between 1 and 1000", read_blocks_2d);
}

TEST(ReadDomainTest, EqualCornersAreAnError) {
  const CaseFile case_file =
      CaseFile::parse("[domain]\nmin = [0.0, 0.0, 0.0]\nmax = [1.0, 0.0, 1.0]\n", "domain.toml");
  try {
    read_domain<3>(case_file);
    FAIL() << "a flat domain was accepted";
  } catch (const CaseError& error) {
    EXPECT_EQ(error.file(), "domain.toml");
    EXPECT_EQ(error.key(), "domain.max");
    EXPECT_NE(error.reason().find("must be greater than domain.min"), std::string::npos);
  }
}

TEST(ReadDomainTest, MissingDomainIsAnError) {
  const CaseFile case_file = CaseFile::parse("model = \"wcsph\"\n", "domain.toml");
  try {
    read_domain<2>(case_file);
    FAIL() << "a case without [domain] was accepted";
  } catch (const CaseError& error) {
    EXPECT_EQ(error.key(), "domain.min");
    EXPECT_NE(error.reason().find("missing required key"), std::string::npos);
  }
}

TEST(ReadDomainTest, ThreeDimensionalDomainIsRead) {
  const CaseFile case_file =
      CaseFile::parse("[domain]\nmin = [0, 0, 0]\nmax = [1.0, 2.0, 3.0]\n", "domain.toml");
  const Box<3> domain = read_domain<3>(case_file);
  EXPECT_EQ(domain.min, (Vec<3>{0.0, 0.0, 0.0}));
  EXPECT_EQ(domain.max, (Vec<3>{1.0, 2.0, 3.0}));
}

} // namespace
} // namespace revsph
