#pragma once
// A defect of a built-in case for the models' bad-input tests: the case with one line edited
// and/or one --set, run with `revsph run`, must end with the one-line error
// "revsph: error: FILE: KEY: REASON", exit status 2, and no output written.

#include "case_text.hpp"
#include "cli_sandbox.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace revsph::testing {

struct CaseDefect {
  const char* name;
  const char* builtin_case;
  const char* from; // a line of the case replaced by `to` ("" for none)
  const char* to;
  const char* set; // a --set argument ("" for none)
  const char* key; // the key the error names
  const char* reason;
};

inline void expect_case_defect_rejected(const CaseDefect& defect) {
  Sandbox sandbox;
  std::string text = builtin_case_text(defect.builtin_case);
  if (std::string(defect.from).size() > 0) {
    text = replaced_once(text, defect.from, defect.to);
  }
  const auto case_path = sandbox.write_case(text);
  std::vector<std::string> arguments{
      "run", case_path.string(), "--out", sandbox.out().string(), "--steps", "1"};
  if (std::string(defect.set).size() > 0) {
    arguments.insert(arguments.end(), {"--set", defect.set});
  }
  const auto result = sandbox.revsph(arguments);
  expect_clean_rejection(
      sandbox, result, {"case.toml"},
      {defect.reason, error_prefix + case_path.string() + ": " + defect.key + ": "});
}

inline std::string case_defect_name(const ::testing::TestParamInfo<CaseDefect>& info) {
  return info.param.name;
}

} // namespace revsph::testing

// The tests Defects/<suite>.RunExitsWithOneLineAndWritesNothing/<name>, one for each CaseDefect in
// the vector `defects`: each must be rejected (expect_case_defect_rejected).
#define REVSPH_CASE_DEFECT_TESTS(suite, defects)                                                   \
  class suite : public ::testing::TestWithParam<::revsph::testing::CaseDefect> {};                 \
  TEST_P(suite, RunExitsWithOneLineAndWritesNothing) {                                             \
    ::revsph::testing::expect_case_defect_rejected(GetParam());                                    \
  }                                                                                                \
  INSTANTIATE_TEST_SUITE_P(Defects, suite, ::testing::ValuesIn(defects),                           \
                           ::revsph::testing::case_defect_name)
