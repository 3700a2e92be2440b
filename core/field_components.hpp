#pragma once
// The names of a field's components, one rule for every place that spells them out (point-file
// columns, and with them a user's own initial fields): a scalar is its name; a vector of D
// components is name_x, name_y, name_z; a D x D tensor, stored row-major (T(i, j) at i * D + j),
// is name_xx, name_xy, ..., name_zz; any other count is name_0, name_1, ... (a 3D spin has 3
// components and is a vector by this rule, a 2D one is a scalar).

#include <string>
#include <vector>

namespace revsph {

inline std::string component_suffix(int dimension, int components, int component) {
  static constexpr char axes[] = "xyz";
  if (components == 1) {
    return "";
  }
  if (components == dimension) {
    return std::string("_") + axes[component];
  }
  if (components == dimension * dimension) {
    return std::string("_") + axes[component / dimension] + axes[component % dimension];
  }
  return "_" + std::to_string(component);
}

// The components' labels without the field's name (x, y; xx, xy, yx, yy), recorded with each
// multi-component dataset of a snapshot (attribute component_names): the columns' order.
inline std::vector<std::string> component_labels(int dimension, int components) {
  std::vector<std::string> labels;
  for (int c = 0; components > 1 && c < components; ++c) {
    labels.push_back(component_suffix(dimension, components, c).substr(1));
  }
  return labels;
}

inline std::string component_name(const std::string& field, int dimension, int components,
                                  int component) {
  return field + component_suffix(dimension, components, component);
}

} // namespace revsph
