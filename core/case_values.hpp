#pragma once
// Checks and defaults that every model's case reader needs beyond core/case_file.hpp.

#include "core/case_file.hpp"
#include "fixedpoint/scale.hpp"

#include <initializer_list>
#include <span>
#include <string>

namespace revsph {

// A quantity derived from valid inputs can still overflow to infinity or underflow to zero
// (dr = 1e300 with support_radius_over_dr = 1e10, say): refused with the key that sets it.
void require_positive_finite(const CaseFile& case_file, const char* key, const char* what,
                             double value);

// The fixed-point scale given as a power-of-two exponent under `key`, or by default the scale
// that covers `magnitude` with `fraction_bits` bits below it.
fixedpoint::Scale scale_or(const CaseFile& case_file, const char* key, double magnitude,
                           int fraction_bits);

// Positions keep this many fraction bits below the domain's largest coordinate by default, so
// that the double view of a position is exact.
constexpr int position_fraction_bits = 52;
// Masses are constants of the set-up: this many fraction bits below the largest keep their
// double view exact.
constexpr int mass_fraction_bits = 52;

// The scale of a model's particle masses: covering the largest of `masses` (one list per set)
// with mass_fraction_bits. Fails `density_key` unless that mass is positive and finite (a density
// times the lattice cell volume can overflow or underflow even when both are valid).
fixedpoint::Scale mass_scale(const CaseFile& case_file, const char* density_key,
                             std::initializer_list<std::span<const double>> masses);

// The positions' scale: fixed_point.position_exponent, or by default the one that covers the
// domain's largest coordinate with 52 fraction bits. Either way its unit must resolve dr to
// 2^-16 (a domain at most 2^36 dr across by default): coarser, the lattice would be rounded onto
// itself and particles would coincide.
fixedpoint::Scale position_scale_or(const CaseFile& case_file, double max_abs_coordinate,
                                    double dr);

// "1.234e-05" with `digits` digits after the point: values of a setup report and its messages.
std::string format_scientific(double value, int digits);

} // namespace revsph
