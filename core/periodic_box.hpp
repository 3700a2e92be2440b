#pragma once
// Periodic boundaries (docs/design/periodic.md): which axes of [domain] are periodic, the exact
// wrap of a position into the period, and which images of a particle its neighbours across a
// periodic face need.
//
// A position is a raw integer at its field's scale. The period of axis k in raw units is
// P = raw(max) - raw(min), an exact integer whatever the scale, and the wrap
// x -> lo + mod(x - lo, P) is addition modulo P: a drift x -> wrap(x + round(dt v)) is undone by
// x -> wrap(x - round(dt v)) bit for bit, so the palindromes stay exactly invertible.

#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace revsph {

struct PeriodicBox {
  std::array<bool, 3> periodic{};
  std::array<double, 3> min{};
  std::array<double, 3> max{};

  bool any() const { return periodic[0] || periodic[1] || periodic[2]; }
  double length(int k) const { return max[k] - min[k]; }
};

// One image of a particle: on each axis -1, 0 or +1 periods added to its position.
using ImageShift = std::array<std::int8_t, 3>;

// The images a particle at `point` (metres, `dimension` coordinates) needs so that every
// particle within `margin` of it across a periodic face finds it: +1 on an axis where it lies
// within `margin` of the lower face (its image sits beyond the upper one), -1 near the upper
// face, and every combination of those at edges and corners; the unshifted position is not among
// them. Written into `shifts` (cleared first; a caller looping over particles keeps its storage).
// Needs 2 margin < the period (one image per axis at most): PeriodicBox users check it.
inline void image_shifts(const double* point, int dimension, const PeriodicBox& box, double margin,
                         std::vector<ImageShift>& shifts) {
  shifts.clear();
  for (int k = 0; k < dimension; ++k) {
    if (!box.periodic[k]) {
      continue;
    }
    std::int8_t towards = 0;
    if (point[k] - box.min[k] < margin) {
      towards = 1;
    } else if (box.max[k] - point[k] < margin) {
      towards = -1;
    }
    if (towards == 0) {
      continue;
    }
    // The shift along k alone, then the images so far shifted along k too.
    const std::size_t before = shifts.size();
    ImageShift alone{};
    alone[k] = towards;
    shifts.push_back(alone);
    for (std::size_t s = 0; s < before; ++s) {
      ImageShift shifted = shifts[s];
      shifted[k] = towards;
      shifts.push_back(shifted);
    }
  }
}

inline std::vector<ImageShift> image_shifts(const double* point, int dimension,
                                            const PeriodicBox& box, double margin) {
  std::vector<ImageShift> shifts;
  image_shifts(point, dimension, box, margin, shifts);
  return shifts;
}

// "x", "y", "z" for messages.
inline std::string axis_name(int k) {
  return std::string(1, static_cast<char>('x' + k));
}

// A period too short for one image per axis (the CLI reports it as a case error on
// domain.periodic).
class PeriodTooShort : public std::invalid_argument {
public:
  using std::invalid_argument::invalid_argument;
};

// Throws PeriodTooShort unless every periodic axis is longer than twice `reach` (image_shifts'
// condition); `what` names the reach in the message.
inline void require_room_for_images(const PeriodicBox& box, int dimension, double reach,
                                    const std::string& what) {
  for (int k = 0; k < dimension; ++k) {
    if (box.periodic[k] && !(box.length(k) > 2.0 * reach)) {
      throw PeriodTooShort("the period along " + axis_name(k) + " (" +
                           std::to_string(box.length(k)) + " m) must exceed twice " + what + " (" +
                           std::to_string(reach) + " m)");
    }
  }
}

} // namespace revsph
