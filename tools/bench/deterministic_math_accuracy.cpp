// Accuracy and cost of revsph's deterministic transcendental functions (SLEEF's "cinz" scalar
// variants, fixedpoint/deterministic_math.hpp) against glibc's, with MPFR as the exact reference.
//
// For each function and input range the models use: the largest error in units of the last place
// (ulp of the exact value, from a 256-bit MPFR result), the share of results equal to the
// correctly rounded double (MPFR at 53 bits, round to nearest), and nanoseconds per call.
//
//   build/bin/deterministic_math_accuracy > docs/deterministic-math-accuracy.csv

#include "fixedpoint/deterministic_math.hpp"

#include <mpfr.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace {

using Mpfr1 = int (*)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t);
using Mpfr2 = int (*)(mpfr_ptr, mpfr_srcptr, mpfr_srcptr, mpfr_rnd_t);

struct Function {
  std::string name;
  std::string range; // as printed
  double low, high;  // inputs drawn uniformly from [low, high]
  double second_low = 0.0, second_high = 0.0;
  std::function<double(double, double)> ours;
  std::function<double(double, double)> glibc;
  Mpfr1 exact1 = nullptr;
  Mpfr2 exact2 = nullptr;
};

struct Errors {
  double largest_ulp = 0.0;
  std::int64_t correctly_rounded = 0;
};

// |value - exact| in ulps of the exact value, and whether value is the correctly rounded double.
void measure(double value, double x, double y, const Function& f, Errors& errors) {
  mpfr_t in_x, in_y, exact, rounded, difference;
  mpfr_inits2(256, in_x, in_y, exact, difference, static_cast<mpfr_ptr>(nullptr));
  mpfr_init2(rounded, 53);
  mpfr_set_d(in_x, x, MPFR_RNDN);
  mpfr_set_d(in_y, y, MPFR_RNDN);
  if (f.exact1 != nullptr) {
    f.exact1(exact, in_x, MPFR_RNDN);
    f.exact1(rounded, in_x, MPFR_RNDN);
  } else {
    f.exact2(exact, in_x, in_y, MPFR_RNDN);
    f.exact2(rounded, in_x, in_y, MPFR_RNDN);
  }
  const double correct = mpfr_get_d(rounded, MPFR_RNDN);
  if (value == correct) {
    ++errors.correctly_rounded;
  }
  mpfr_sub_d(difference, exact, value, MPFR_RNDN);
  const int exponent = mpfr_get_exp(exact); // exact = m 2^exponent, 0.5 <= |m| < 1
  const double ulp = std::ldexp(1.0, exponent - 53);
  const double error = std::fabs(mpfr_get_d(difference, MPFR_RNDN)) / ulp;
  errors.largest_ulp = std::max(errors.largest_ulp, error);
  mpfr_clears(in_x, in_y, exact, rounded, difference, static_cast<mpfr_ptr>(nullptr));
}

double nanoseconds_per_call(const std::function<double(double, double)>& f,
                            const std::vector<double>& xs, const std::vector<double>& ys) {
  volatile double sink = 0.0;
  const auto start = std::chrono::steady_clock::now();
  for (int repeat = 0; repeat < 5; ++repeat) {
    for (std::size_t i = 0; i < xs.size(); ++i) {
      sink = sink + f(xs[i], ys[i]);
    }
  }
  const std::chrono::duration<double, std::nano> elapsed = std::chrono::steady_clock::now() - start;
  return elapsed.count() / (5.0 * static_cast<double>(xs.size()));
}

std::vector<Function> functions() {
  constexpr double pi = std::numbers::pi;
  namespace d = revsph::dmath;
  auto one = [](double (*f)(double)) { return [f](double x, double) { return f(x); }; };
  auto two = [](double (*f)(double, double)) {
    return [f](double x, double y) { return f(x, y); };
  };
  return {
      {"exp", "[-30, 30]", -30, 30, 0, 0, one(d::exp), one(::exp), mpfr_exp},
      {"expm1", "[-1, 1]", -1, 1, 0, 0, one(d::expm1), one(::expm1), mpfr_expm1},
      {"log", "[1e-6, 1e6]", 1e-6, 1e6, 0, 0, one(d::log), one(::log), mpfr_log},
      {"log (near 1)", "[0.5, 2]", 0.5, 2, 0, 0, one(d::log), one(::log), mpfr_log},
      {"log1p", "[-0.5, 10]", -0.5, 10, 0, 0, one(d::log1p), one(::log1p), mpfr_log1p},
      {"pow", "[0.5, 2] ^ [-2, 8]", 0.5, 2, -2, 8, two(d::pow), two(::pow), nullptr, mpfr_pow},
      {"sin", "[-pi, pi]", -pi, pi, 0, 0, one(d::sin), one(::sin), mpfr_sin},
      {"cos", "[-pi, pi]", -pi, pi, 0, 0, one(d::cos), one(::cos), mpfr_cos},
      {"tan", "[-pi/2.2, pi/2.2]", -pi / 2.2, pi / 2.2, 0, 0, one(d::tan), one(::tan), mpfr_tan},
      {"acos", "[-1, 1]", -1, 1, 0, 0, one(d::acos), one(::acos), mpfr_acos},
      {"atan2", "[-1, 1] x [-1, 1]", -1, 1, -1, 1, two(d::atan2), two(::atan2), nullptr,
       mpfr_atan2},
      {"sinh", "[-2, 2]", -2, 2, 0, 0, one(d::sinh), one(::sinh), mpfr_sinh},
      {"cosh", "[-2, 2]", -2, 2, 0, 0, one(d::cosh), one(::cosh), mpfr_cosh},
      {"tanh", "[-2, 2]", -2, 2, 0, 0, one(d::tanh), one(::tanh), mpfr_tanh},
      {"hypot", "[-1, 1] x [-1, 1]", -1, 1, -1, 1, two(d::hypot), two(::hypot), nullptr,
       mpfr_hypot},
  };
}

} // namespace

int main() {
  constexpr std::size_t samples = 200000;
  std::mt19937_64 random(20261129);
  std::printf("function,range,samples,revsph_largest_ulp,revsph_correctly_rounded,"
              "glibc_largest_ulp,glibc_correctly_rounded,revsph_ns_per_call,glibc_ns_per_call\n");
  for (const Function& f : functions()) {
    std::uniform_real_distribution<double> first(f.low, f.high);
    std::uniform_real_distribution<double> second(f.second_low, f.second_high);
    std::vector<double> xs(samples), ys(samples);
    for (std::size_t i = 0; i < samples; ++i) {
      xs[i] = first(random);
      ys[i] = f.exact2 != nullptr ? second(random) : 0.0;
    }
    Errors ours, glibc;
    for (std::size_t i = 0; i < samples; ++i) {
      measure(f.ours(xs[i], ys[i]), xs[i], ys[i], f, ours);
      measure(f.glibc(xs[i], ys[i]), xs[i], ys[i], f, glibc);
    }
    const auto share = [](std::int64_t n) { return static_cast<double>(n) / samples; };
    std::printf("%s,\"%s\",%zu,%.3f,%.5f,%.3f,%.5f,%.1f,%.1f\n", f.name.c_str(), f.range.c_str(),
                samples, ours.largest_ulp, share(ours.correctly_rounded), glibc.largest_ulp,
                share(glibc.correctly_rounded), nanoseconds_per_call(f.ours, xs, ys),
                nanoseconds_per_call(f.glibc, xs, ys));
  }
  return 0;
}
