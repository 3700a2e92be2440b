#pragma once
// The frame of an analysis program that writes one CSV: `PROGRAM [OUT.csv]` (stdout without an
// argument); a bad command line or an unwritable file exits 2, an error while computing exits 1
// with one line naming the program.

#include <exception>
#include <fstream>
#include <iostream>
#include <string_view>

namespace revsph::analysis {

// write(out) writes the CSV; the exit status of main.
template <class Write>
int run_csv_program(int argc, char** argv, std::string_view program, const Write& write) {
  if (argc > 2) {
    std::cerr << "usage: " << program << " [OUT.csv]\n";
    return 2;
  }
  std::ofstream file;
  if (argc == 2) {
    file.open(argv[1]);
    if (!file) {
      std::cerr << program << ": cannot write " << argv[1] << "\n";
      return 2;
    }
  }
  std::ostream& out = argc == 2 ? file : std::cout;
  try {
    write(out);
  } catch (const std::exception& error) {
    std::cerr << program << ": " << error.what() << "\n";
    return 1;
  }
  return out ? 0 : 1;
}

} // namespace revsph::analysis
