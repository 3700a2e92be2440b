#pragma once
// Units of per-particle extensive quantities in D dimensions: a particle of a 2D run stands for
// a prism of unit depth, so its mass is per metre (kg/m), of a 1D run for a slab of unit area
// (kg/m^2).

namespace revsph {

template <int D>
inline constexpr const char* mass_unit = D == 1 ? "kg/m^2" : (D == 2 ? "kg/m" : "kg");
template <int D>
inline constexpr const char* energy_unit = D == 1 ? "J/m^2" : (D == 2 ? "J/m" : "J");
template <int D>
inline constexpr const char* entropy_unit = D == 1 ? "J/(K m^2)" : (D == 2 ? "J/(K m)" : "J/K");

} // namespace revsph
