// Golden hashes: the state of each built-in case after N steps must keep the hash committed in
// tests/golden_hashes.csv, on any CPU, compiler, thread count and cell size. The same table is
// what tools/cross_cpu/compare-hashes checks a build for another CPU against.

#include "simulation_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct GoldenHash {
  std::string case_name;
  std::int64_t steps = 0;
  std::string hash;
};

// The rows of tests/golden_hashes.csv (header `case,steps,hash`; lines from `#` are comments).
std::vector<GoldenHash> golden_hashes() {
  const std::string path = std::string(REVSPH_SOURCE_DIR) + "/tests/golden_hashes.csv";
  std::ifstream table(path);
  if (!table) {
    throw std::runtime_error("cannot read " + path);
  }
  std::vector<GoldenHash> rows;
  std::string line;
  bool header_seen = false;
  while (std::getline(table, line)) {
    if (line.empty() || line.front() == '#') {
      continue;
    }
    if (!header_seen) {
      header_seen = true;
      continue;
    }
    std::istringstream fields(line);
    GoldenHash row;
    std::string steps;
    std::getline(fields, row.case_name, ',');
    std::getline(fields, steps, ',');
    std::getline(fields, row.hash, ',');
    row.steps = std::stoll(steps);
    rows.push_back(row);
  }
  return rows;
}

// gtest prints a parameter in test listings and failures: the row as in the table.
void PrintTo(const GoldenHash& row, std::ostream* out) {
  *out << row.case_name << ',' << row.steps << ',' << row.hash;
}

class GoldenHashTable : public ::testing::TestWithParam<GoldenHash> {};

TEST_P(GoldenHashTable, StateHashAsCommitted) {
  const GoldenHash& row = GetParam();
  EXPECT_EQ(revsph::testing::hash_after(row.case_name, row.steps), row.hash)
      << "to change it on purpose: build/bin/revsph hash " << row.case_name << " --steps "
      << row.steps << ", and say why in the commit message";
}

INSTANTIATE_TEST_SUITE_P(BuiltInCases, GoldenHashTable, ::testing::ValuesIn(golden_hashes()),
                         [](const ::testing::TestParamInfo<GoldenHash>& info) {
                           std::string name = info.param.case_name + "_" +
                                              std::to_string(info.param.steps) + "_steps";
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

} // namespace
