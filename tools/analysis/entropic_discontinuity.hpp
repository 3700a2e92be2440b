#pragma once
// The discontinuity test of paper 4 (Pavelka, Klika, Kincl 2024, §3.5, Figs. 3-7): density and
// entropy density across a jump in particle spacing, for each particle volume, at t = 0.
//
// 1D, x in (0, 1), the jump at 0.5: spacing 1e-4 on the left and 0.5e-4 on the right, equal
// masses m = 1e-4 (so rho is about 1 on the left and 2 on the right), particle entropy S_a = the
// local spacing (so s = S / V is about 1 everywhere: the paper says "in the left part", but its
// stated aim, an entropy "approximately constant over the whole domain", needs it on both
// sides), Wendland quintic with support radius h = 0.001 (core's 1D kernel, alpha = 3 / (2 h)).
// The lattice continues beyond (0, 1) as dummy particles so that the ends do not cut the sums;
// only particles in (0, 1) are reported. Volumes (eqs. 23-28): mass, entropic, direct, implicit
// (W V = 1 over all particles, conjugate gradients), mixed (rho = sum m W, s = sum S W).

#include <array>
#include <string_view>
#include <vector>

namespace revsph::analysis {

enum class DiscontinuityVolume { mass, entropic, direct, implicit, mixed };
inline constexpr std::array<DiscontinuityVolume, 5> discontinuity_volumes = {
    DiscontinuityVolume::mass, DiscontinuityVolume::entropic, DiscontinuityVolume::direct,
    DiscontinuityVolume::implicit, DiscontinuityVolume::mixed};
std::string_view name_of(DiscontinuityVolume volume);

struct DiscontinuityProfiles {
  std::vector<double> x; // the particles in (0, 1), ascending
  // density[v][i], entropy_density[v][i] for volume v in discontinuity_volumes order.
  std::array<std::vector<double>, 5> density, entropy_density;
};

// The particle entropies S of the right part. The paper sets them "in the left part" equal to the
// spacing and says nothing of the right part; the three readings: the right part's own spacing
// (s about 1 everywhere, the stated aim: the default), the left part's value continued (S the
// same on every particle), zero (only the left part carries entropy, as a code that starts every
// S at 0 would have it). A fourth reading sets both parts alike: s = 1 as an entropy density
// read through the mass volume, S_a = 1 * m_a / sum_b m_b W_ab (a code that starts S from the
// density field it has, the mass volume's), so S follows the mass volume's smoothed step.
enum class RightEntropy { spacing, left_value, zero, mass_volume };
inline constexpr std::array<RightEntropy, 4> right_entropies = {
    RightEntropy::spacing, RightEntropy::left_value, RightEntropy::zero, RightEntropy::mass_volume};
std::string_view name_of(RightEntropy right);

// The profiles; `left_spacing` 1e-4 and h 1e-3 are the paper's (right spacing: half the left).
DiscontinuityProfiles entropic_discontinuity(RightEntropy right = RightEntropy::spacing,
                                             double left_spacing = 1e-4,
                                             double support_radius = 1e-3);

} // namespace revsph::analysis
