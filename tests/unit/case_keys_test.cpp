// The case-key tables (core/case_keys.hpp) are the reference of every key a case file may have:
//
//   - every key the readers read, for every built-in case, is declared (common or model table),
//   - every declaration is documented (meaning, unit, default), and a string key's allowed values
//     are the ones its reader accepts,
//   - reading through undeclared keys, other types or other defaults is a std::logic_error,
//   - the unknown-key error names the command that lists the keys,
//   - docs/case-keys.md is what `revsph cases --keys all --markdown` prints.
//
// The case-file fuzz corpus checks the first point on thousands of mutants (case_fuzz_test.cpp).

#include "core/case_file.hpp"
#include "core/case_keys.hpp"
#include "core/model_registry.hpp"
#include "core/run_settings.hpp"

#include "case_text.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace revsph {
namespace {

const ModelEntry& model_entry(std::string_view name) {
  const ModelEntry* entry = model_registry().find(name);
  if (entry == nullptr || entry->keys == nullptr) {
    throw std::logic_error("no model with a key table named " + std::string(name));
  }
  return *entry;
}

// The keys accessed in `case_file` that neither the common table nor the model's declares.
std::vector<std::string> undeclared_read_keys(const CaseFile& case_file,
                                              const KeyTable& model_keys) {
  std::vector<std::string> undeclared;
  for (const std::string& key : case_file.accessed_keys()) {
    const std::string pattern = key_pattern(key);
    const bool declared =
        common_case_keys().find(pattern) != nullptr || model_keys.find(pattern) != nullptr ||
        common_case_keys().declares_table(pattern) || model_keys.declares_table(pattern);
    if (!declared) {
      undeclared.push_back(key);
    }
  }
  return undeclared;
}

TEST(CaseKeys, KeyPatternDropsArrayIndices) {
  EXPECT_EQ(key_pattern("particles[12].min"), "particles[].min");
  EXPECT_EQ(key_pattern("discretisation.dr"), "discretisation.dr");
  EXPECT_EQ(key_pattern("a[0].b[3].c"), "a[].b[].c");
}

TEST(CaseKeys, EveryKeyReadByEveryBuiltinCaseIsDeclared) {
  for (const BuiltinCase& builtin : builtin_cases()) {
    SCOPED_TRACE(std::string(builtin.name));
    CaseFile case_file = load_case(std::string(builtin.name));
    read_run_settings(case_file);
    const auto simulation = create_simulation(case_file, SimulationOptions{});
    EXPECT_NO_THROW(case_file.require_no_unknown_keys());
    const KeyTable& keys = model_entry(builtin.model).keys();
    EXPECT_EQ(keys.name(), builtin.model);
    EXPECT_GT(case_file.accessed_keys().size(), 10u);
    EXPECT_EQ(undeclared_read_keys(case_file, keys), std::vector<std::string>{});
    // The tables create_simulation attached are the common one and the model's.
    ASSERT_EQ(case_file.key_tables().size(), 2u);
    EXPECT_EQ(case_file.key_tables()[0], &common_case_keys());
    EXPECT_EQ(case_file.key_tables()[1], &keys);
  }
}

void expect_documented(const KeyTable& table) {
  for (const KeyDecl& key : table.keys()) {
    SCOPED_TRACE(table.name() + ": " + key.path);
    EXPECT_FALSE(key.meaning.empty());
    EXPECT_FALSE(key.unit.empty());
    EXPECT_FALSE(key.default_value.empty());
    if (key.type != KeyType::number && key.type != KeyType::numbers) {
      EXPECT_EQ(key.unit, "-") << "only numbers have units";
    }
    if (!key.allowed.empty()) {
      EXPECT_EQ(key.type, KeyType::string);
    }
    // One notation for arrays of tables: "particles[].min", never an index.
    EXPECT_EQ(key_pattern(key.path), key.path);
  }
}

TEST(CaseKeys, EveryDeclarationIsDocumented) {
  expect_documented(common_case_keys());
  ASSERT_FALSE(model_registry().entries().empty());
  for (const ModelEntry& entry : model_registry().entries()) {
    ASSERT_NE(entry.keys, nullptr) << entry.name;
    EXPECT_EQ(entry.keys().name(), entry.name);
    expect_documented(entry.keys());
    for (const KeyDecl& key : entry.keys().keys()) {
      EXPECT_EQ(common_case_keys().find(key.path), nullptr)
          << key.path << " is declared by both the common table and " << entry.name;
    }
  }
}

// A built-in case of each model that reaches every string key's check.
std::string base_case_of(std::string_view model) {
  return model == "wcsph"        ? "dambreak-small"
         : model == "entropic"   ? "expansion-small"
         : model == "superfluid" ? "second-sound-small"
         : model == "two_fluid"  ? "rayleigh-taylor-small"
                                 : "cavity-re100-small";
}

// Setting a string key to a value outside its allowed ones is refused by the reader, on that key,
// with a message naming every allowed value: the table and the reader agree.
TEST(CaseKeys, AllowedValuesAreTheOnesTheReaderNames) {
  for (const ModelEntry& entry : model_registry().entries()) {
    for (const KeyDecl& key : entry.keys().keys()) {
      if (key.allowed.empty()) {
        continue;
      }
      // The first block's key for a block key ("particles[]" -> "particles[0]").
      const std::size_t brackets = key.path.find("[]");
      const std::string concrete =
          brackets == std::string::npos
              ? key.path
              : key.path.substr(0, brackets) + "[0]" + key.path.substr(brackets + 2);
      SCOPED_TRACE(entry.name + ": " + concrete);
      CaseFile case_file = load_case(base_case_of(entry.name));
      case_file.set(concrete, "\"not-a-value\"");
      try {
        read_run_settings(case_file);
        create_simulation(case_file, SimulationOptions{});
        ADD_FAILURE() << "a value outside the allowed ones was accepted";
      } catch (const CaseError& error) {
        EXPECT_EQ(error.key(), concrete);
        for (const std::string& value : key.allowed) {
          EXPECT_NE(error.reason().find("\"" + value + "\""), std::string::npos)
              << value << " not in: " << error.reason();
        }
      }
    }
  }
}

KeyTable test_table() {
  KeyTable table("test");
  table.add({"a.x", KeyType::number, "m", "0.5", "a number with a default"});
  table.add({"a.n", KeyType::integer, "-", "3", "an integer with a default"});
  table.add({"a.s", KeyType::string, "-", "\"one\"", "a string", {"one", "two"}});
  table.add({"a.b", KeyType::boolean, "-", "true", "a boolean"});
  table.add({"a.free", KeyType::number, "m", "dr", "a default described, not compared"});
  table.add({"blocks", KeyType::tables, "-", "required", "blocks"});
  table.add({"blocks[].p", KeyType::numbers, "m", "required", "a point"});
  return table;
}

TEST(CaseKeys, ReadingThroughTheTablesCatchesReaderBugs) {
  const KeyTable table = test_table();
  const CaseFile case_file =
      CaseFile::parse("[a]\nx = 1.0\n[[blocks]]\np = [1.0, 2.0]\n", "test.toml");
  case_file.use_keys({&table});
  EXPECT_EQ(case_file.number("a.x"), 1.0);
  EXPECT_EQ(case_file.number_or("a.x", 0.5), 1.0);
  EXPECT_EQ(case_file.integer_or("a.n", 3), 3);
  EXPECT_EQ(case_file.string_or("a.s", "one"), "one");
  EXPECT_TRUE(case_file.boolean_or("a.b", true));
  EXPECT_EQ(case_file.number_or("a.free", 7.0), 7.0);
  EXPECT_EQ(case_file.table_count("blocks"), 1u);
  EXPECT_EQ(case_file.numbers("blocks[0].p", 2)[1], 2.0);
  // Undeclared keys, in any accessor.
  EXPECT_THROW(case_file.number("a.y"), std::logic_error);
  EXPECT_THROW(case_file.has("b"), std::logic_error);
  EXPECT_THROW(case_file.numbers("blocks[0].q", 2), std::logic_error);
  EXPECT_THROW(case_file.accept_table("c"), std::logic_error);
  EXPECT_NO_THROW(case_file.accept_table("a"));
  // Another type than declared.
  EXPECT_THROW(case_file.integer("a.x"), std::logic_error);
  EXPECT_THROW(case_file.string_or("a.n", "3"), std::logic_error);
  // Another default than declared.
  EXPECT_THROW(case_file.number_or("a.x", 0.25), std::logic_error);
  EXPECT_THROW(case_file.integer_or("a.n", 4), std::logic_error);
  EXPECT_THROW(case_file.string_or("a.s", "two"), std::logic_error);
  EXPECT_THROW(case_file.boolean_or("a.b", false), std::logic_error);
}

TEST(CaseKeys, KeysReadBeforeTheTablesAreCheckedWhenTheyArrive) {
  const KeyTable table = test_table();
  const CaseFile case_file = CaseFile::parse("[a]\nx = 1.0\n", "test.toml");
  EXPECT_EQ(case_file.number("a.x"), 1.0);
  EXPECT_EQ(case_file.number_or("a.undeclared", 2.0), 2.0); // no tables yet: not checked
  EXPECT_THROW(case_file.use_keys({&table}), std::logic_error);
}

// The CaseError with which `case_file`, read as the command line reads it, refuses its unknown
// keys; if it has none, a failure and nothing.
std::optional<CaseError> unknown_key_error(CaseFile& case_file) {
  read_run_settings(case_file);
  create_simulation(case_file, SimulationOptions{});
  try {
    case_file.require_no_unknown_keys();
  } catch (const CaseError& error) {
    return error;
  }
  ADD_FAILURE() << "the unknown key was accepted";
  return std::nullopt;
}

TEST(CaseKeys, UnknownKeyNamesTheCommandListingTheKeys) {
  for (const std::string& model : {std::string("wcsph"), std::string("shtc")}) {
    CaseFile case_file = load_case(base_case_of(model));
    case_file.set("discretisation.bogus_key", "0.1"); // no declared key near it
    if (const auto error = unknown_key_error(case_file)) {
      EXPECT_EQ(error->key(), "discretisation.bogus_key");
      EXPECT_EQ(error->reason(),
                "unknown key (given with --set; every key: revsph cases --keys " + model + ")");
    }
  }
}

TEST(CaseKeys, UnknownKeySuggestsTheNearestDeclaredOne) {
  const std::vector<const KeyTable*> tables = {&common_case_keys(), &model_entry("wcsph").keys()};
  EXPECT_EQ(nearest_declared_key(tables, "discretisation.drr"), "discretisation.dr");
  EXPECT_EQ(nearest_declared_key(tables, "walls.epsilon"), "wall.epsilon");
  EXPECT_EQ(nearest_declared_key(tables, "particles[3].lattise"), "particles[3].lattice");
  EXPECT_EQ(nearest_declared_key(tables, "dimensions"), "dimension");
  EXPECT_EQ(nearest_declared_key(tables, "colour"), "");
  EXPECT_EQ(nearest_declared_key(tables, "particles[0].colour"), "");

  CaseFile case_file = load_case("dambreak-small");
  case_file.set("physics.sound_sped", "100");
  if (const auto error = unknown_key_error(case_file)) {
    EXPECT_EQ(error->reason(), "unknown key (given with --set; every key: revsph cases --keys "
                               "wcsph); did you mean physics.sound_speed?");
  }
}

TEST(CaseKeys, DeclaredKeyLeftUnreadSaysItIsNotUsedRatherThanSuggestingItself) {
  // a.n is declared but this reader never asks for it (as a model skips a key its other settings
  // make irrelevant): suggesting "a.n" for "a.n" would only puzzle.
  const KeyTable table = test_table();
  const CaseFile case_file = CaseFile::parse("[a]\nx = 1.0\nn = 4\n", "test.toml");
  case_file.use_keys({&table});
  EXPECT_EQ(case_file.number("a.x"), 1.0);
  try {
    case_file.require_no_unknown_keys();
    ADD_FAILURE() << "the unused key was accepted";
  } catch (const CaseError& error) {
    EXPECT_EQ(error.key(), "a.n");
    EXPECT_EQ(error.reason(), "not used with this case's other settings (line 3; what each key "
                              "needs: revsph cases --keys test)");
  }
}

std::string command_output(const std::string& command) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) {
    throw std::runtime_error("cannot run " + command);
  }
  std::string output;
  std::array<char, 4096> buffer{};
  while (const std::size_t n = fread(buffer.data(), 1, buffer.size(), pipe.get())) {
    output.append(buffer.data(), n);
  }
  return output;
}

TEST(CaseKeysDoc, CommittedReferenceIsWhatTheBinaryPrints) {
  std::ifstream in(std::string(REVSPH_SOURCE_DIR) + "/docs/case-keys.md", std::ios::binary);
  ASSERT_TRUE(in) << "docs/case-keys.md is missing";
  std::ostringstream committed;
  committed << in.rdbuf();
  const std::string printed =
      command_output(std::string(REVSPH_BINARY) + " cases --keys all --markdown");
  EXPECT_EQ(committed.str(), printed)
      << "docs/case-keys.md is stale: regenerate it with "
         "build/bin/revsph cases --keys all --markdown > docs/case-keys.md";
}

TEST(CaseKeysDoc, TextReferenceListsEveryKeyOfTheModel) {
  for (const ModelEntry& entry : model_registry().entries()) {
    const std::string printed =
        command_output(std::string(REVSPH_BINARY) + " cases --keys " + entry.name);
    for (const KeyTable* table : {&common_case_keys(), &entry.keys()}) {
      for (const KeyDecl& key : table->keys()) {
        EXPECT_NE(printed.find("  " + key.path + "  ("), std::string::npos)
            << entry.name << ": " << key.path;
      }
    }
  }
}

} // namespace
} // namespace revsph
