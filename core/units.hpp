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
template <int D>
inline constexpr const char* momentum_unit = D == 1 ? "kg/(m s)" : (D == 2 ? "kg/s" : "kg m/s");
// m x v summed over the particles (about the z axis in 2D).
template <int D>
inline constexpr const char* angular_momentum_unit = D == 1 ? "kg/s"
                                                            : (D == 2 ? "kg m/s" : "kg m^2/s");
template <int D>
inline constexpr const char* power_unit = D == 1 ? "W/m^2" : (D == 2 ? "W/m" : "W");
// A region's extent: a length in 1D, an area in 2D (per metre of depth), a volume in 3D.
template <int D>
inline constexpr const char* volume_unit = D == 1 ? "m" : (D == 2 ? "m^2" : "m^3");

// The same for a dimension known at run time.
inline constexpr const char* energy_unit_of(int dimension) {
  return dimension == 1 ? energy_unit<1> : (dimension == 2 ? energy_unit<2> : energy_unit<3>);
}

} // namespace revsph
