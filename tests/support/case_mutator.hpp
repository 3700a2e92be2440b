#pragma once
// The mutations of the case-file fuzz test (tests/unit/case_fuzz_test.cpp): byte edits (NUL,
// non-UTF-8, quotes, brackets, '=', newlines), line edits, numbers replaced by extreme ones,
// values replaced by other types, renamed keys, inserted keys and tables, truncation, random
// --set overrides, and combinations of these, from one seed.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace revsph::testing {

// Keys a case may have, and some it may not.
inline const std::vector<std::string>& key_names() {
  // clang-format off
  static const std::vector<std::string> names = {
      "model", "dimension", "name", "rest_density", "sound_speed", "gravity",
      "gravity_reference_height", "dr", "support_radius_over_dr", "courant_number", "dt",
      "cell_size_factor", "radius_over_dr", "energy_per_mass", "epsilon", "min", "max", "kind",
      "shape", "lattice", "spacing", "layers", "open_top", "t_end", "steps", "energy_every",
      "snapshot_every", "progress_interval", "position_exponent", "velocity_exponent",
      "density_exponent", "acceleration_exponent", "particles", "physics", "domain", "wall", "run",
      "output", "fixed_point", "discretisation", "x", "dr2", "DR", "\"quoted key\"",
      "'literal key'", "\"\"", "a.b", "physics.dr", "domain.min", "particles.kind", "min.x",
      "\"dr\"", "d r", "1", "-", "_", "health", "max_energy_error", "max_speed_over_c",
      "close_pair_fraction"};
  // clang-format on
  return names;
}

inline const std::vector<std::string>& table_headers() {
  // clang-format off
  static const std::vector<std::string> headers = {
      "[physics]", "[discretisation]", "[wall]", "[domain]", "[run]", "[output]", "[fixed_point]",
      "[[particles]]", "[particles]", "[[physics]]", "[domain.min]", "[particles.0]",
      "[[particles.kind]]", "[]", "[[]]", "[ physics ]", "[\"physics\"]", "[run.steps]",
      "[[domain]]", "[x]", "[physics.dr]", "[health]", "[[health]]"};
  // clang-format on
  return headers;
}

// Bytes that matter to a TOML parser or to UTF-8 handling.
// clang-format off
inline constexpr std::array<char, 34> special_bytes = {
    '\0', '\n', '\r', '\t', ' ', '"', '\'', '[', ']', '{', '}', '=', '#', '.', ',', '\\', '-', '+',
    '_', 'e', 'E', '0', '1', '9', ':', 'T', 'Z', static_cast<char>(0x80), static_cast<char>(0xc3),
    static_cast<char>(0xe2), static_cast<char>(0xf0), static_cast<char>(0xff),
    static_cast<char>(0xfe), static_cast<char>(0xc0)};
// clang-format on

class Mutator {
public:
  explicit Mutator(std::uint64_t seed) : random_(seed) {}

  std::size_t below(std::size_t n) { return n == 0 ? 0 : random_() % n; }
  bool chance(double p) { return std::uniform_real_distribution<double>(0.0, 1.0)(random_) < p; }
  template <class T>
  const T& pick(const std::vector<T>& items) {
    return items[below(items.size())];
  }

  char random_byte() {
    if (chance(0.6)) {
      return special_bytes[below(special_bytes.size())];
    }
    return static_cast<char>(below(256));
  }

  std::string random_number() {
    // clang-format off
    static const std::vector<std::string> extremes = {
        "0", "-0", "0.0", "-0.0", "+0.0", "1", "-1", "2", "3", "4", "-1.0", "0.5", "1e308",
        "-1e308", "1.7976931348623157e308", "1e309", "-1e309", "1e-300", "-1e-300", "4.9e-324",
        "1e-320", "2.2250738585072014e-308", "1e-400", "nan", "+nan", "-nan", "inf", "+inf",
        "-inf", "9223372036854775807", "-9223372036854775808", "9223372036854775808",
        "18446744073709551616", "2147483647", "2147483648", "-2147483649", "4294967296", "1000",
        "1001", "-1000", "-1001", "1e3", "1.0e3", "1e10", "1e20", "1e-10", "0x7fffffffffffffff",
        "0xff", "0o777", "0b101", "1_000", "1__0", "_1", "1.", ".5", "1e", "1e+", "--1", "+-1",
        "0001", "00.5", "1.5e3.2", "1,5", "6.02214076e23", "1E2", "1e0", "0e0", "0e-0", "-0e0",
        "12345678901234567890", "1e100", "-1e100", "1e-100", "1e150", "1e155", "1e200", "-1e200",
        "1e-200", "1e-160", "1e-310"};
    // clang-format on
    switch (below(6)) {
    case 0:
    case 1:
      return pick(extremes);
    case 2: { // log-uniform double of either sign
      const double magnitude =
          std::pow(10.0, std::uniform_real_distribution<double>(-12, 12)(random_));
      std::ostringstream out;
      out << std::setprecision(static_cast<int>(1 + below(17)))
          << (chance(0.2) ? -1 : 1) * magnitude;
      std::string text = out.str();
      if (text.find_first_of(".eEn") == std::string::npos && chance(0.5)) {
        text += ".0";
      }
      return text;
    }
    case 3: { // integer of a random size
      const int bits = static_cast<int>(below(63));
      const std::int64_t value = static_cast<std::int64_t>(random_() >> (63 - bits));
      return std::to_string(chance(0.2) ? -value : value);
    }
    case 4: { // very long digit strings
      const std::size_t length = 20 + below(600);
      std::string digits(length, '0');
      for (char& d : digits) {
        d = static_cast<char>('0' + below(10));
      }
      switch (below(3)) {
      case 0:
        digits[0] = '1';
        return digits;
      case 1:
        return digits.insert(0, "0.");
      default:
        return digits.insert(0, "1.") + "e" + std::to_string(static_cast<int>(below(700)) - 350);
      }
    }
    default: { // small values near the base case's scale, appended piecewise (GCC 12 warns
               // falsely, -Wrestrict, about "e" + std::string)
      std::string text = std::to_string(static_cast<int>(below(7)) - 1);
      if (chance(0.5)) {
        text += ".0";
      }
      if (chance(0.3)) {
        text += 'e';
        text += std::to_string(static_cast<int>(below(9)) - 4);
      }
      return text;
    }
    }
  }

  std::string random_value() {
    // clang-format off
    static const std::vector<std::string> strings = {
        "\"fluid\"", "\"wall\"", "\"box\"", "\"container\"", "\"hexagonal\"", "\"square\"",
        "\"wcsph\"", "\"\"", "\"\\u0000\"", "\"\\uD800\"", "'literal'", "\"\"\"multi\nline\"\"\"",
        "'''raw\n'''", "\"\xff\xfe\"", "\"\xc3\x28\"", "\"fluid\\n\"", "\"a\\tb\"", "\"FLUID\"",
        "\"dambreak-small\"", "\"../../etc/passwd\"", "\"\\\"\"", "\"unterminated", "true",
        "false", "TRUE", "yes", "1979-05-27T07:32:00Z", "1979-05-27", "07:32:00", "{}",
        "{ a = 1 }", "{ min = [0.0, 0.0] }", "{ kind = \"fluid\" }", "[]", "[[]]", "[{}]",
        "[\"a\", \"b\"]", "[1, \"a\"]", "[true, false]", "[[1.0, 2.0], [3.0, 4.0]]", "[1.0,]",
        "[,]", "[1.0 2.0]", "[", "]", "=", ""};
    // clang-format on
    switch (below(5)) {
    case 0:
    case 1:
      return random_number();
    case 2:
      return pick(strings);
    default: { // an array of 0 to 4 numbers (right and wrong lengths)
      std::string array = "[";
      const std::size_t length = below(5);
      for (std::size_t i = 0; i < length; ++i) {
        array += (i ? ", " : "") + random_number();
      }
      return array + (chance(0.1) ? ",]" : "]");
    }
    }
  }

  // One mutation of `text`.
  void mutate(std::string& text) {
    switch (below(14)) {
    case 0: // delete characters
      if (!text.empty()) {
        const std::size_t at = below(text.size());
        text.erase(at, 1 + below(std::min<std::size_t>(8, text.size() - at)));
      }
      break;
    case 1: // insert a byte (or a few)
      for (std::size_t n = 1 + below(3); n > 0; --n) {
        text.insert(text.begin() + static_cast<std::ptrdiff_t>(below(text.size() + 1)),
                    random_byte());
      }
      break;
    case 2: // replace a byte
      if (!text.empty()) {
        text[below(text.size())] = random_byte();
      }
      break;
    case 3:
    case 4:
    case 5: // replace a number
      replace_number(text);
      break;
    case 6:
    case 7: // replace a value by another of any type
      replace_value(text);
      break;
    case 8: { // delete, duplicate or swap lines
      std::vector<std::string> lines = split_lines(text);
      if (lines.empty()) {
        break;
      }
      const std::size_t a = below(lines.size());
      const std::size_t b = below(lines.size());
      switch (below(3)) {
      case 0:
        lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(a));
        break;
      case 1:
        lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(b), lines[a]);
        break;
      default:
        std::swap(lines[a], lines[b]);
      }
      text = join_lines(lines);
      break;
    }
    case 9: // rename a key
      rename_key(text);
      break;
    case 10:
    case 11: { // insert a key (known or not) or a table header
      std::vector<std::string> lines = split_lines(text);
      const std::string line =
          chance(0.25) ? pick(table_headers()) : pick(key_names()) + " = " + random_value();
      lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(below(lines.size() + 1)), line);
      text = join_lines(lines);
      break;
    }
    case 12: // truncate
      text.resize(below(text.size() + 1));
      break;
    default: { // change a table header
      std::vector<std::string> lines = split_lines(text);
      std::vector<std::size_t> headers;
      for (std::size_t i = 0; i < lines.size(); ++i) {
        if (!lines[i].empty() && lines[i][0] == '[') {
          headers.push_back(i);
        }
      }
      if (!headers.empty()) {
        lines[pick(headers)] = pick(table_headers());
        text = join_lines(lines);
      }
    }
    }
  }

  // A --set override: a key of the case (or not) and a value.
  std::pair<std::string, std::string> random_override() {
    // clang-format off
    static const std::vector<std::string> keys = {
        "discretisation.dr", "discretisation.dt", "discretisation.courant_number",
        "discretisation.support_radius_over_dr", "discretisation.cell_size_factor",
        "physics.sound_speed", "physics.rest_density", "physics.gravity", "dimension", "model",
        "name", "domain.min", "domain.max", "particles[0].min", "particles[1].max",
        "particles[0].kind", "particles[1].shape", "particles[1].layers", "particles[0].lattice",
        "particles[0].spacing", "particles[2].min", "particles[99999999999999999999].min",
        "particles[-1].min", "particles[x].min", "particles[].min", "particles[0]",
        "particles[0].min[0]", "particles.kind", "run.steps", "run.t_end", "run",
        "output.energy_every", "fixed_point.position_exponent", "fixed_point.velocity_exponent",
        "fixed_point.density_exponent", "fixed_point.acceleration_exponent",
        "health.max_energy_error", "health.max_speed_over_c", "health.close_pair_fraction",
        "health", "a..b", ".a", "a.",
        "", "physics.rest_density.x", "domain.min.x", "wall", "wall.epsilon", "x.y.z"};
    // clang-format on
    std::string value = chance(0.2) ? std::string(1, random_byte()) : random_value();
    return {pick(keys), value};
  }

private:
  static std::vector<std::string> split_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start <= text.size()) {
      const std::size_t end = text.find('\n', start);
      if (end == std::string::npos) {
        lines.push_back(text.substr(start));
        break;
      }
      lines.push_back(text.substr(start, end - start));
      start = end + 1;
    }
    return lines;
  }
  static std::string join_lines(const std::vector<std::string>& lines) {
    std::string text;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      text += (i ? "\n" : "") + lines[i];
    }
    return text;
  }

  static bool number_char(char c) {
    return (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-' ||
           c == '_';
  }

  // Replaces a number token (a digit with its neighbouring number characters).
  void replace_number(std::string& text) {
    std::vector<std::pair<std::size_t, std::size_t>> numbers;
    for (std::size_t i = 0; i < text.size();) {
      if (text[i] >= '0' && text[i] <= '9') {
        std::size_t begin = i;
        while (begin > 0 && number_char(text[begin - 1]) && text[begin - 1] != '_') {
          --begin;
        }
        std::size_t end = i;
        while (end < text.size() && number_char(text[end])) {
          ++end;
        }
        numbers.emplace_back(begin, end);
        i = end;
      } else {
        ++i;
      }
    }
    if (numbers.empty()) {
      return;
    }
    const auto [begin, end] = numbers[below(numbers.size())];
    text.replace(begin, end - begin, random_number());
  }

  // Replaces what follows the '=' of a random "key = value" line (up to a comment).
  void replace_value(std::string& text) {
    std::vector<std::size_t> equals;
    for (std::size_t i = 0; i < text.size(); ++i) {
      if (text[i] == '=') {
        equals.push_back(i);
      }
    }
    if (equals.empty()) {
      return;
    }
    const std::size_t at = equals[below(equals.size())] + 1;
    std::size_t end = text.find_first_of("#\n", at);
    end = end == std::string::npos ? text.size() : end;
    std::string value = " ";
    value += random_value();
    value += ' ';
    text.replace(at, end - at, value);
  }

  // Replaces the key of a random "key = value" line.
  void rename_key(std::string& text) {
    std::vector<std::size_t> line_starts;
    for (std::size_t i = 0; i < text.size(); ++i) {
      if ((i == 0 || text[i - 1] == '\n') && text.find('=', i) < text.find('\n', i)) {
        line_starts.push_back(i);
      }
    }
    if (line_starts.empty()) {
      return;
    }
    const std::size_t start = line_starts[below(line_starts.size())];
    const std::size_t equals = text.find('=', start);
    std::string key = pick(key_names());
    if (chance(0.3)) { // or the old key, slightly wrong
      key = text.substr(start, equals - start);
      while (!key.empty() && key.back() == ' ') {
        key.pop_back();
      }
      key += chance(0.5) ? "s" : "_";
    }
    text.replace(start, equals - start, key + " ");
  }

  std::mt19937_64 random_;
};

} // namespace revsph::testing
