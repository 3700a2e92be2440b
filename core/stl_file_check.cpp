#include "core/stl_file_check.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <vector>

namespace revsph {

namespace {

std::vector<std::string> words_of(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string word; in >> word;) {
    words.push_back(word);
  }
  return words;
}

// Whether words[first..first+3) are three numbers (finite ones if `finite`).
bool three_numbers(const std::vector<std::string>& words, std::size_t first, bool finite) {
  if (words.size() != first + 3) {
    return false;
  }
  for (std::size_t i = first; i < first + 3; ++i) {
    const std::string& word = words[i];
    double value = 0.0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (error != std::errc() || end != word.data() + word.size() ||
        (finite && !std::isfinite(value))) {
      return false;
    }
  }
  return true;
}

// Where the reader is in the grammar (stl_file_check.hpp).
enum class Expect { solid, facet, loop, vertex, endfacet };

// The triangle count of a binary file's header (little-endian), or nothing if it has none.
std::optional<std::uintmax_t> binary_triangle_count(const std::string& bytes) {
  if (bytes.size() < 84) {
    return std::nullopt;
  }
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(bytes[80 + i]); };
  return byte(0) | (byte(1) << 8) | (byte(2) << 16) | (static_cast<std::uintmax_t>(byte(3)) << 24);
}

std::optional<std::string> ascii_fault(const std::string& bytes);

std::optional<std::string> binary_fault(const std::string& bytes) {
  const std::optional<std::uintmax_t> count = binary_triangle_count(bytes);
  if (!count || bytes.size() != 84 + 50 * *count) {
    return std::nullopt; // not binary STL either: CGAL's reader refuses it
  }
  for (std::uintmax_t t = 0; t < *count; ++t) {
    std::array<float, 12> values{}; // the normal, then three corners
    std::memcpy(values.data(), bytes.data() + 84 + 50 * t, sizeof values);
    for (std::size_t k = 3; k < values.size(); ++k) {
      if (!std::isfinite(values[k])) {
        return "triangle " + std::to_string(t + 1) +
               ": a corner's coordinate is not a finite number";
      }
    }
  }
  return std::nullopt;
}

} // namespace

bool is_ascii_stl(const std::string& bytes) {
  std::istringstream in(bytes);
  std::string first;
  if (!(in >> first) || first != "solid") {
    return false;
  }
  const std::optional<std::uintmax_t> triangles = binary_triangle_count(bytes);
  return !triangles || bytes.size() != 84 + 50 * *triangles;
}

std::optional<std::string> stl_file_fault(const std::string& bytes) {
  return is_ascii_stl(bytes) ? ascii_fault(bytes) : binary_fault(bytes);
}

namespace {

std::optional<std::string> ascii_fault(const std::string& bytes) {
  std::istringstream in(bytes);
  Expect expect = Expect::solid;
  int vertices = 0;
  std::size_t number = 0;
  std::string line;
  auto fault = [&](const std::string& reason) {
    return "line " + std::to_string(number) + ": " + reason + " (\"" + line + "\")";
  };
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') {
      line.pop_back();
    }
    const std::vector<std::string> words = words_of(line);
    if (words.empty()) {
      continue;
    }
    const std::string& word = words[0];
    switch (expect) {
    case Expect::solid:
      if (word != "solid") {
        return fault("expected \"solid\"");
      }
      expect = Expect::facet;
      break;
    case Expect::facet:
      if (word == "endsolid") {
        expect = Expect::solid;
      } else if (word == "facet" && words.size() >= 2 && words[1] == "normal" &&
                 three_numbers(words, 2, false)) {
        expect = Expect::loop;
      } else {
        return fault("expected \"facet normal NX NY NZ\" or \"endsolid\"");
      }
      break;
    case Expect::loop:
      if (words.size() != 2 || word != "outer" || words[1] != "loop") {
        return fault("expected \"outer loop\"");
      }
      expect = Expect::vertex;
      vertices = 0;
      break;
    case Expect::vertex:
      if (word == "endloop" && words.size() == 1) {
        if (vertices != 3) {
          return fault("a facet of " + std::to_string(vertices) +
                       " vertices: only triangles are read");
        }
        expect = Expect::endfacet;
      } else if (word != "vertex" || !three_numbers(words, 1, true)) {
        return fault("expected \"vertex X Y Z\" with three finite numbers");
      } else if (++vertices > 3) {
        return fault("a facet of more than 3 vertices: only triangles are read");
      }
      break;
    case Expect::endfacet:
      if (word != "endfacet" || words.size() != 1) {
        return fault("expected \"endfacet\"");
      }
      expect = Expect::facet;
      break;
    }
  }
  if (expect != Expect::solid) {
    return "line " + std::to_string(number) + ": the file ends inside a solid (no \"endsolid\")";
  }
  return std::nullopt;
}

} // namespace

} // namespace revsph
