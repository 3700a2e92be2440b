#pragma once
// Images of the particles near the periodic faces (core/periodic_box.hpp) as ghost slots of
// their sets' fields (core/state_field.hpp): a pair pass over the carriers then reaches across
// the faces with no minimum image in any pair term.
//
// During a run the distribution keeps them (core/distributed/state_distribution.hpp, on one
// process as on many: images travel as ghosts with a shift). A set-up that sums over pairs
// before the run (a model's integration constants, say) places them once with
// attach_periodic_images: the ghosts are then copies without an exchange plan, whose own sums a
// pair pass computes and nobody reads.

#include "core/particle_sets.hpp"
#include "core/periodic_wrap.hpp"
#include "core/state_field.hpp"

#include <cstdint>
#include <type_traits>
#include <vector>

namespace revsph {

// Which particles need which images: row n is particle particle[n] shifted by shift[n].
struct ImageList {
  std::vector<std::uint32_t> particle;
  std::vector<ImageShift> shift;
};

// The images of `count` particles at points[i * dimension + k] (metres) within `margin` of a
// periodic face.
inline ImageList image_list(const std::vector<double>& points, int dimension,
                            const PeriodicBox& box, double margin) {
  ImageList images;
  std::vector<ImageShift> shifts;
  const auto d = static_cast<std::size_t>(dimension);
  for (std::size_t i = 0; d > 0 && i < points.size() / d; ++i) {
    image_shifts(points.data() + i * d, dimension, box, margin, shifts);
    for (const ImageShift& shift : shifts) {
      images.particle.push_back(static_cast<std::uint32_t>(i));
      images.shift.push_back(shift);
    }
  }
  return images;
}

// Component c of an image of position `x`: x plus its shift's periods, in raw units.
template <class Raw>
Raw shifted(Raw x, const RawPeriod<Raw>& period, const ImageShift& shift, int c) {
  return shift[c] == 0 ? x : x + static_cast<Raw>(shift[c]) * period.period[c];
}

// Whether some set's positions are periodic (fill_set set them so from [domain] periodic).
template <DeclaredState State>
bool has_periodic_positions(State& state) {
  bool periodic = false;
  for_each_field(state, [&](const auto& field) {
    periodic = periodic || (field.info().name == "position" && field.info().period.any());
  });
  return periodic;
}

// Places the images within `margin` of the periodic faces as every set's ghosts (see above).
// Sets without a periodic position field are left as they are.
template <DeclaredState State>
void attach_periodic_images(State& state, double margin) {
  for_each_set(state, [&](auto& set) {
    using Field = std::remove_cvref_t<decltype(std::get<0>(set.fields()))>;
    using Raw = typename Field::value_type;
    const Field* position = nullptr;
    for_each_field_of(set, [&](const Field& field) {
      if (field.info().name == "position" && field.info().period.any()) {
        position = &field;
      }
    });
    if (position == nullptr) {
      return;
    }
    const int d = position->components();
    require_room_for_images(position->info().period, d, margin, "the set-up's interaction radius");
    std::vector<double> points(position->count() * static_cast<std::size_t>(d));
    for (std::size_t i = 0; i < position->count(); ++i) {
      for (int k = 0; k < d; ++k) {
        points[i * static_cast<std::size_t>(d) + static_cast<std::size_t>(k)] =
            static_cast<double>(position->at(k, i));
      }
    }
    // The margin and the faces in the position's raw units (exact for the integers of fixed
    // point up to 2^53, which is only a choice of images, never a result).
    const RawPeriod<Raw> raw = raw_period<Raw>(position->info());
    PeriodicBox box = position->info().period;
    double raw_margin = margin;
    if constexpr (!std::is_same_v<Raw, double>) {
      raw_margin = margin / position->info().scale.unit();
    }
    for (int k = 0; k < 3; ++k) {
      box.min[k] = static_cast<double>(raw.lower[k]);
      box.max[k] = static_cast<double>(raw.lower[k] + raw.period[k]);
    }
    const ImageList images = image_list(points, d, box, raw_margin);
    const std::size_t n = images.particle.size();
    for_each_field_of(set, [&](Field& field) {
      const int components = field.components();
      const bool is_position = field.info().name == "position";
      std::vector<Raw> values(n * static_cast<std::size_t>(components));
      for (int c = 0; c < components; ++c) {
        for (std::size_t g = 0; g < n; ++g) {
          const Raw x = field.at(c, images.particle[g]);
          values[static_cast<std::size_t>(c) * n + g] =
              is_position ? shifted(x, raw, images.shift[g], c) : x;
        }
      }
      field.set_ghosts(n, std::move(values));
    });
  });
}

} // namespace revsph
