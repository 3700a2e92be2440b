#pragma once
// Running the revsph binary in a scratch directory and checking how it refuses bad input: shared
// by the CLI tests. Header-only: REVSPH_BINARY is defined for each test program
// (tests/CMakeLists.txt).
//
// Every run happens in a fresh temporary working directory that holds only what the test put
// there, so a stray file (a default out/ directory, a log) shows up as well as the --out
// directory.

#include "temp_directory.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <set>
#include <string>
#include <vector>

namespace revsph::testing {

inline const std::string error_prefix = "revsph: error: ";

inline std::string shell_quoted(const std::string& word) {
  std::string quoted = "'";
  for (char c : word) {
    quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  }
  return quoted + "'";
}

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline std::set<std::string> entries_of(const std::filesystem::path& directory) {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    names.insert(entry.path().filename().string());
  }
  return names;
}

struct CommandResult {
  int exit_status = -1;
  std::string out;
  std::string err;
};

inline std::ostream& operator<<(std::ostream& stream, const CommandResult& result) {
  return stream << "exit status " << result.exit_status << "\n--- stdout:\n"
                << result.out << "--- stderr:\n"
                << result.err << "---";
}

// A scratch area: `work()` is the binary's working directory and holds the case file; the
// captured output lives beside it, so that work() shows exactly what the binary wrote.
class Sandbox {
public:
  Sandbox() { std::filesystem::create_directory(work()); }

  std::filesystem::path work() const { return root_.path() / "work"; }
  std::filesystem::path out() const { return work() / "out"; }

  std::filesystem::path write_case(const std::string& text,
                                   const std::string& name = "case.toml") const {
    const std::filesystem::path path = work() / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  CommandResult revsph(const std::vector<std::string>& arguments) const {
    const std::filesystem::path out_file = root_.path() / "stdout.txt";
    const std::filesystem::path err_file = root_.path() / "stderr.txt";
    // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on `" " + string`.
    std::string command = "cd ";
    command.append(shell_quoted(work().string()))
        .append(" && ")
        .append(shell_quoted(REVSPH_BINARY));
    for (const std::string& argument : arguments) {
      command.append(" ").append(shell_quoted(argument));
    }
    command.append(" </dev/null >").append(shell_quoted(out_file.string()));
    command.append(" 2>").append(shell_quoted(err_file.string()));
    const int status = std::system(command.c_str());
    CommandResult result;
    result.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = read_file(out_file);
    result.err = read_file(err_file);
    return result;
  }

private:
  TempDirectory root_{"revsph-cli-test"};
};

// The contract for every rejected input. `parts` must all appear in the one error line.
inline void expect_clean_rejection(const Sandbox& sandbox, const CommandResult& result,
                                   const std::set<std::string>& expected_work_entries,
                                   const std::vector<std::string>& parts) {
  EXPECT_EQ(result.exit_status, 2) << result;
  EXPECT_EQ(result.out, "") << result;
  EXPECT_EQ(result.err.rfind(error_prefix, 0), 0u) << result;
  ASSERT_FALSE(result.err.empty()) << result;
  EXPECT_EQ(result.err.back(), '\n') << result;
  EXPECT_EQ(result.err.find('\n'), result.err.size() - 1) << "more than one line: " << result;
  for (const std::string& part : parts) {
    EXPECT_NE(result.err.find(part), std::string::npos)
        << "the message lacks \"" << part << "\": " << result;
  }
  EXPECT_FALSE(std::filesystem::exists(sandbox.out())) << "the --out directory was created";
  EXPECT_EQ(entries_of(sandbox.work()), expected_work_entries) << "something was written";
}

} // namespace revsph::testing
