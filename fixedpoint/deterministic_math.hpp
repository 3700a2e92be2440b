#pragma once
// Transcendental functions whose bits are the same on every CPU (design note §6).
//
// glibc's exp, log, pow, sin, … are not correctly rounded, and glibc picks a different variant
// (with or without FMA) for each CPU, so their last bits follow the machine. Every transcendental
// value that reaches the state (set-up, equations of state, distortion steps, sources) comes from
// here instead: SLEEF's deterministic scalar variants ("cinz": no FMA, pure C), which SLEEF builds
// to return the same bits on every platform. Accuracy is 1.0 ulp ("u10"; hypot 0.5 ulp), measured
// against MPFR by tools/bench/deterministic_math_accuracy (docs/deterministic-math-accuracy.md).
//
// Debian's sleef.h declares the scalar pure-C variants only on some architectures; they are
// exported by libsleef on all of them, so they are declared here.

extern "C" {
double Sleef_cinz_expd1_u10purec(double);
double Sleef_cinz_expm1d1_u10purec(double);
double Sleef_cinz_logd1_u10purec(double);
double Sleef_cinz_log1pd1_u10purec(double);
double Sleef_cinz_powd1_u10purec(double, double);
double Sleef_cinz_sind1_u10purec(double);
double Sleef_cinz_cosd1_u10purec(double);
double Sleef_cinz_tand1_u10purec(double);
double Sleef_cinz_acosd1_u10purec(double);
double Sleef_cinz_atan2d1_u10purec(double, double);
double Sleef_cinz_sinhd1_u10purec(double);
double Sleef_cinz_coshd1_u10purec(double);
double Sleef_cinz_tanhd1_u10purec(double);
double Sleef_cinz_hypotd1_u05purec(double, double);
}

namespace revsph::dmath {

inline double exp(double x) {
  return Sleef_cinz_expd1_u10purec(x);
}
inline double expm1(double x) {
  return Sleef_cinz_expm1d1_u10purec(x);
}
inline double log(double x) {
  return Sleef_cinz_logd1_u10purec(x);
}
inline double log1p(double x) {
  return Sleef_cinz_log1pd1_u10purec(x);
}
inline double pow(double x, double y) {
  return Sleef_cinz_powd1_u10purec(x, y);
}
inline double sin(double x) {
  return Sleef_cinz_sind1_u10purec(x);
}
inline double cos(double x) {
  return Sleef_cinz_cosd1_u10purec(x);
}
inline double tan(double x) {
  return Sleef_cinz_tand1_u10purec(x);
}
inline double acos(double x) {
  return Sleef_cinz_acosd1_u10purec(x);
}
inline double atan2(double y, double x) {
  return Sleef_cinz_atan2d1_u10purec(y, x);
}
inline double sinh(double x) {
  return Sleef_cinz_sinhd1_u10purec(x);
}
inline double cosh(double x) {
  return Sleef_cinz_coshd1_u10purec(x);
}
inline double tanh(double x) {
  return Sleef_cinz_tanhd1_u10purec(x);
}
inline double hypot(double x, double y) {
  return Sleef_cinz_hypotd1_u05purec(x, y);
}

// x^n by multiplication in a fixed order (design note §6: integer powers never go through pow).
inline double integer_power(double x, int n) {
  double product = 1.0;
  for (int i = 0; i < (n < 0 ? -n : n); ++i) {
    product *= x;
  }
  return n < 0 ? 1.0 / product : product;
}

} // namespace revsph::dmath
