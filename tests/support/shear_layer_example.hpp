#pragma once
// The periodic shear layer of docs/examples/periodic-shear-layer in a sandbox: its case file and
// a point file of cells x cells particles made by the example's own make_points.py. Header-only,
// for the CLI tests.

#include "cli_sandbox.hpp"

#include <cstdlib>
#include <filesystem>
#include <string>

namespace revsph::testing {

// Writes shear-layer.toml and shear_layer.csv into the sandbox's working directory; false if the
// point file could not be made.
inline bool write_shear_layer_example(const Sandbox& sandbox, int cells) {
  const std::filesystem::path example =
      std::filesystem::path(REVSPH_SOURCE_DIR) / "docs" / "examples" / "periodic-shear-layer";
  std::filesystem::copy_file(example / "shear-layer.toml", sandbox.work() / "shear-layer.toml");
  const std::string make = "cd '" + sandbox.work().string() + "' && /usr/bin/python3 '" +
                           (example / "make_points.py").string() + "' --cells " +
                           std::to_string(cells) + " --out shear_layer.csv > /dev/null";
  return std::system(make.c_str()) == 0;
}

} // namespace revsph::testing
