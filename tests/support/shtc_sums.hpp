#pragma once
// The SHTC-SPH pair sums of a test cloud, in the points' order: each call sorts the points into a
// fresh slot layout (core/slot_layout.hpp), runs the model's pair term and maps the results back.

#include "models/shtc/forces.hpp"
#include "models/shtc/kernel_sums.hpp"
#include "models/shtc/mirrored_walls.hpp"
#include "models/shtc/sum_scales.hpp"
#include "models/shtc/velocity_gradient.hpp"

#include "cell_ordered_cloud.hpp"

#include <vector>

namespace revsph::testing {

// Scales for the test clouds (masses ~1, spacing 0.1: densities ~100): finer than the model's
// defaults, so that the tests' tolerances see the pair loops, not the rounding of their terms.
inline shtc::SumScales test_sum_scales() {
  return {fixedpoint::Scale::covering(1e3, 52), fixedpoint::Scale::covering(1e4, 50),
          fixedpoint::Scale::covering(1e4, 50), fixedpoint::Scale::covering(1e2, 50)};
}

// rho, lambda, H and H^-1 with C_rho = 0 and the given C_lambda (empty: zero).
template <int D>
shtc::KernelSums<D> kernel_sums_of(const WendlandQuintic<D>& kernel, const CoordinateArrays<D>& x,
                                   const std::vector<double>& mass,
                                   const std::vector<double>& lambda_constant = {}) {
  const SlotLayout<D> layout = layout_over<D>(x, kernel.support_radius());
  const fixedpoint::Scale scale = test_sum_scales().density;
  std::vector<std::int64_t> density_raw(mass.size(), 0);
  std::vector<std::int64_t> lambda_raw(mass.size(), 0);
  for (std::size_t i = 0; i < lambda_constant.size(); ++i) {
    lambda_raw[i] = fixedpoint::to_fixed(lambda_constant[i], scale, "lambda constant");
  }
  shtc::KernelSums<D> slots(scale);
  shtc::compute_kernel_sums<D>(kernel, layout, to_slots<D>(layout, mass),
                               to_slots<D>(layout, density_raw), to_slots<D>(layout, lambda_raw),
                               slots);
  shtc::KernelSums<D> sums(scale);
  sums.density = to_points<D>(layout, slots.density);
  sums.lambda = to_points<D>(layout, slots.lambda);
  sums.h_matrix = to_points<D>(layout, slots.h_matrix);
  sums.h_inverse = to_points<D>(layout, slots.h_inverse);
  return sums;
}

template <int D>
std::vector<shtc::GradientMatrix<D>>
velocity_gradients_of(const WendlandQuintic<D>& kernel, const CoordinateArrays<D>& x,
                      const CoordinateArrays<D>& v, const std::vector<double>& mass) {
  const SlotLayout<D> layout = layout_over<D>(x, kernel.support_radius());
  const shtc::KernelSums<D> sums = kernel_sums_of<D>(kernel, x, mass);
  const CoordinateArrays<D> slot_v = to_slots<D>(layout, v);
  shtc::VelocityGradients<D> gradients(test_sum_scales().velocity_sum);
  shtc::velocity_gradients<D>(kernel, layout, view_of<D>(slot_v), to_slots<D>(layout, mass),
                              to_slots<D>(layout, sums.h_inverse), gradients);
  return to_points<D>(layout, gradients.gradient);
}

template <int D>
CoordinateArrays<D> acceleration_of(const WendlandQuintic<D>& kernel, double penalty_strength,
                                    const CoordinateArrays<D>& x, const std::vector<double>& mass,
                                    const std::vector<shtc::GradientMatrix<D>>& stress,
                                    const std::vector<double>& lambda) {
  const SlotLayout<D> layout = layout_over<D>(x, kernel.support_radius());
  auto sums = shtc::acceleration_sums<D>(test_sum_scales().acceleration);
  CoordinateArrays<D> acceleration;
  shtc::compute_acceleration<D>(kernel, penalty_strength, layout, to_slots<D>(layout, mass),
                                to_slots<D>(layout, stress), to_slots<D>(layout, lambda), sums,
                                acceleration);
  return to_points<D>(layout, acceleration);
}

// The velocities with the wall points' replaced by their mirrored ones.
template <int D>
CoordinateArrays<D>
mirrored_velocities(const WendlandQuintic<D>& kernel, const CoordinateArrays<D>& x,
                    const std::vector<double>& mass, const std::vector<std::uint8_t>& is_wall,
                    const CoordinateArrays<D>& velocity) {
  const SlotLayout<D> layout = layout_over<D>(x, kernel.support_radius());
  const shtc::SumScales scales = test_sum_scales();
  auto sums = shtc::mirror_sums<D>(scales.density, scales.mirror_velocity_sum);
  CoordinateArrays<D> slot_velocity = to_slots<D>(layout, velocity);
  // One set here: the walls are told by a 0/1 byte per slot read as two "sets" (0 and 1: mask 0b10).
  const std::vector<std::uint8_t> wall_of_slot = to_slots<D>(layout, is_wall);
  shtc::mirror_wall_velocities<D>(kernel, layout, to_slots<D>(layout, mass),
                                  SlotInSet{wall_of_slot, 0b10}, slot_velocity, sums);
  return to_points<D>(layout, slot_velocity);
}

} // namespace revsph::testing
