#pragma once
// The one point where a case's `dimension` becomes the template parameter D: a model's setup
// names the dimensions it implements and gets its creator instantiated for each,
//   with_dimension<1, 2, 3>(case_file, [&]<int D>() { return create<D>(case_file); });
// and a case asking for another dimension gets one error naming the ones that exist.

#include "core/arithmetic.hpp"
#include "core/case_file.hpp"

#include <cstdint>
#include <string>

namespace revsph {

template <int... Dimensions, class Create>
auto with_dimension(const CaseFile& case_file, Create&& create) {
  static_assert(sizeof...(Dimensions) > 0 && ((Dimensions >= 1 && Dimensions <= 3) && ...));
  const std::int64_t dimension = case_file.integer("dimension");
  using Result = decltype(create.template operator()<(Dimensions, ...)>());
  Result result{};
  const bool found =
      ((dimension == Dimensions ? (result = create.template operator()<Dimensions>(), true)
                                : false) ||
       ...);
  if (!found) {
    // "2 or 3", "1, 2 or 3"
    const int dimensions[] = {Dimensions...};
    std::string allowed;
    for (std::size_t i = 0; i < sizeof...(Dimensions); ++i) {
      allowed += (i == 0                           ? ""
                  : i + 1 == sizeof...(Dimensions) ? " or "
                                                   : ", ") +
                 std::to_string(dimensions[i]);
    }
    case_file.fail("dimension", "must be " + allowed + " for this model (got " +
                                    std::to_string(dimension) + ")");
  }
  return result;
}

// The same for the arithmetic, a model templated on FixedArithmetic and FloatArithmetic:
//   with_arithmetic(options.arithmetic, [&]<class Arith>() { return create<D, Arith>(...); });
template <class Create>
auto with_arithmetic(Arithmetic arithmetic, Create&& create) {
  if (arithmetic == Arithmetic::fixed) {
    return create.template operator()<FixedArithmetic>();
  }
  return create.template operator()<FloatArithmetic>();
}

// Both, for a model templated on the dimension and the arithmetic:
//   with_dimension_and_arithmetic<2, 3>(case_file, options.arithmetic,
//                                       [&]<int D, class Arith>() { return create<D, Arith>(...); });
template <int... Dimensions, class Create>
auto with_dimension_and_arithmetic(const CaseFile& case_file, Arithmetic arithmetic,
                                   Create&& create) {
  return with_dimension<Dimensions...>(case_file, [&]<int D>() {
    return with_arithmetic(arithmetic,
                           [&]<class Arith>() { return create.template operator()<D, Arith>(); });
  });
}

} // namespace revsph
