#pragma once
// The two-fluid model's hydrostatic start (initial.hydrostatic): the particle masses of a column
// at rest under gravity.

#include "core/geometry.hpp"
#include "models/two_fluid/parameters.hpp"

#include <array>
#include <span>

namespace revsph::two_fluid {

// The fluid and the walls start compressed as a column at rest under
// gravity. The pressure at a particle is background_pressure plus rho_k g dr for every fluid
// particle above it in its lattice column (half for itself), rho_k each one's rest density; a
// wall particle takes the column of the nearest fluid particle's x and the normal fluid's rest
// density (walls are frozen normal fluid). Its mass is the Tait density of that pressure,
// rho_k (1 + (p - p_b) / B)^(1 / gamma) with B = rho_k c^2 / gamma, over its own number density
// n = sum_b W_ab at the start (exact sums, as the model's): so rho = m n (eq. 36) is the column's
// at every particle, next to walls too, where 1 / dr^D would leave the outer wall layers short
// and the kernel sum's lattice bias (0.5 % at 3 dr) would give the two fluids' Tait laws
// different pressures at rest.
//
// position and mass: the superfluid, normal and wall particles, in that order; the masses are
// overwritten.
template <int D>
void hydrostatic_masses(const Parameters<D>& p, std::array<std::span<const Vec<D>>, 3> position,
                        std::array<std::span<double>, 3> mass);

} // namespace revsph::two_fluid
