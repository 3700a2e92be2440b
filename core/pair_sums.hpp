#pragma once
// The accumulators of one pair loop (core/pair_sum.hpp): K quantities per slot, each at its own
// fixed-point scale, and their values after the loop.
//
// FixedArithmetic: every term is rounded once to its quantity's scale and added in integers
// (design note §3), so a total is the same for any order of its terms. A slot's running totals
// are 64-bit with overflow detection (a total that leaves int64 is invalid, even if later terms
// would bring it back; the pair list fixes the order of the terms, so that verdict is
// reproducible too); the partial sum of a slot's own partners is 128-bit. FloatArithmetic (FloPA):
// plain doubles added in the order the terms come. The K totals of a slot are stored together,
// so adding a pair's terms to its partner touches one cache line, not K.

#include "core/arithmetic.hpp"
#include "fixedpoint/conversion.hpp"
#include "fixedpoint/exact_sum.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

namespace revsph {

// A quantity a pair loop sums: its name in fault reports and its fixed-point scale.
struct SummedQuantity {
  const char* name;
  fixedpoint::Scale scale;
};

// K components of one quantity (a vector's), all at the same scale.
template <int K>
std::array<SummedQuantity, K> components_of(const char* name, const fixedpoint::Scale& scale) {
  std::array<SummedQuantity, K> quantities{};
  quantities.fill({name, scale});
  return quantities;
}

template <class Arith, int K>
class PairSums {
  static_assert(K >= 1 && K <= 32, "a pair loop sums 1 to 32 quantities");
  static constexpr bool exact = Arith::kind == Arithmetic::fixed;
  // In floating point a single quantity's totals are its values (no second array).
  static constexpr bool values_are_totals = !exact && K == 1;

public:
  using Raw = typename Arith::Raw;
  using Total = std::conditional_t<exact, std::int64_t, double>;
  // One bit per quantity: a byte for up to 8 (most loops), so that the bits cost 1 byte a slot.
  using Bits = std::conditional_t<K <= 8, std::uint8_t,
                                  std::conditional_t<K <= 16, std::uint16_t, std::uint32_t>>;

  explicit PairSums(const std::array<SummedQuantity, K>& quantities) : quantities_(quantities) {
    for (int q = 0; q < K; ++q) {
      inverse_unit_[q] = quantities[q].scale.inverse_unit();
    }
  }
  explicit PairSums(const SummedQuantity& quantity) requires(K == 1)
      : PairSums(std::array<SummedQuantity, 1>{quantity}) {}

  // Quantity q of slot s after the loop (zero for a slot the term does not receive).
  double value(int q, std::size_t slot) const {
    if constexpr (values_are_totals) {
      return totals_[slot];
    } else {
      return values_[q][slot];
    }
  }
  std::span<const double> values(int q) const {
    if constexpr (values_are_totals) {
      return totals_;
    } else {
      return values_[q];
    }
  }
  // The exact total of quantity q in slot s, in raw units of its scale (fixed point; valid after
  // the loop for a slot whose sums converted): what a state update adds without a rounding of
  // its own (a momentum kick made of pair impulses, say).
  std::int64_t raw_total(int q, std::size_t slot) const requires(exact) {
    return totals_[slot * K + q];
  }
  const std::array<SummedQuantity, K>& quantities() const { return quantities_; }

  // The partial sums of one slot's own partners (128-bit in fixed point: they cannot overflow).
  class Local {
  public:
    explicit Local(const PairSums& sums) : sums_(sums) {}
    void add(int q, double term) {
      if constexpr (exact) {
        std::int64_t raw = 0;
        if (sums_.to_fixed(q, term, raw)) {
          total_[q] += raw;
        } else {
          invalid_ |= 1u << q;
        }
      } else {
        total_[q] += term;
      }
    }

  private:
    friend class PairSums;
    const PairSums& sums_;
    std::array<std::conditional_t<exact, fixedpoint::int128, double>, K> total_{};
    std::uint32_t invalid_ = 0;
  };

  // n slots, every total zero and valid.
  void reset(std::size_t n) {
    resize(n);
#pragma omp parallel
    zero_in_team();
  }
  // The two halves of reset for a pair loop that runs in one parallel region: resize before it,
  // zero_in_team in it (by every thread of the team).
  void resize(std::size_t n) {
    totals_.resize(n * K);
    if constexpr (exact) {
      invalid_.resize(n); // floating-point totals carry their own verdict (not finite)
    }
    resize_values(n);
  }
  void zero_in_team() {
    const std::size_t n = totals_.size() / K;
#pragma omp for schedule(static)
    for (std::size_t s = 0; s < n; ++s) {
      for (int q = 0; q < K; ++q) {
        totals_[s * K + q] = Total{};
      }
      if constexpr (exact) {
        invalid_[s] = 0;
      }
    }
  }
  void add(std::size_t slot, int q, double term) {
    if constexpr (exact) {
      std::int64_t raw = 0;
      if (!to_fixed(q, term, raw) ||
          __builtin_add_overflow(totals_[slot * K + q], raw, &totals_[slot * K + q])) {
        invalid_[slot] |= static_cast<Bits>(1u << q);
      }
    } else {
      totals_[slot * K + q] += term;
    }
  }
  // A value already in raw units of the quantity's scale (a stored constant).
  void add_raw(std::size_t slot, int q, Raw raw) {
    if constexpr (exact) {
      if (__builtin_add_overflow(totals_[slot * K + q], raw, &totals_[slot * K + q])) {
        invalid_[slot] |= static_cast<Bits>(1u << q);
      }
    } else {
      totals_[slot * K + q] += raw;
    }
  }
  void add_local(std::size_t slot, const Local& local) {
    if constexpr (exact) {
      invalid_[slot] |= static_cast<Bits>(local.invalid_);
      for (int q = 0; q < K; ++q) {
        const fixedpoint::int128 total = local.total_[q];
        if (total > INT64_MAX || total < INT64_MIN) {
          invalid_[slot] |= static_cast<Bits>(1u << q);
        } else {
          add_raw(slot, q, static_cast<std::int64_t>(total));
        }
      }
    } else {
      for (int q = 0; q < K; ++q) {
        totals_[slot * K + q] += local.total_[q];
      }
    }
  }
  // Converts slot s's totals into values(); false for the first quantity that overflowed or is
  // not finite (its index in `failed`).
  bool convert(std::size_t slot, int& failed) {
    if constexpr (values_are_totals) {
      failed = 0;
      return std::isfinite(totals_[slot]);
    } else {
      for (int q = 0; q < K; ++q) {
        double& value = values_[q][slot];
        if constexpr (exact) {
          if ((invalid_[slot] >> q) & 1u) {
            failed = q;
            return false;
          }
          value = fixedpoint::to_real(totals_[slot * K + q], quantities_[q].scale);
        } else {
          value = totals_[slot * K + q];
          if (!std::isfinite(value)) {
            failed = q;
            return false;
          }
        }
      }
      return true;
    }
  }
  // A slot's totals and values, as a distributed run copies them from a particle's owner to its
  // ghost slots (SlotLayout::copy_to_ghost_slots).
  struct SlotRow {
    std::array<Total, K> totals;
    std::array<double, K> values;
  };
  void row(std::size_t slot, SlotRow& out) const {
    for (int q = 0; q < K; ++q) {
      out.totals[q] = totals_[slot * K + q];
      out.values[q] = value(q, slot);
    }
  }
  void set_row(std::size_t slot, const SlotRow& in) {
    for (int q = 0; q < K; ++q) {
      totals_[slot * K + q] = in.totals[q];
      if constexpr (!values_are_totals) {
        values_[q][slot] = in.values[q];
      }
    }
    if constexpr (exact) {
      invalid_[slot] = 0;
    }
  }

  void resize_values(std::size_t n) {
    if constexpr (!values_are_totals) {
      for (int q = 0; q < K; ++q) {
        values_[q].resize(n);
      }
    }
  }
  void clear_values(std::size_t slot) {
    if constexpr (values_are_totals) {
      totals_[slot] = 0.0;
    } else {
      for (int q = 0; q < K; ++q) {
        values_[q][slot] = 0.0;
      }
    }
  }

private:
  // raw = round(term / unit) as fixedpoint::try_to_fixed, with the quantity's 1 / unit at hand.
  bool to_fixed(int q, double term, std::int64_t& raw) const {
    const double quotient = term * inverse_unit_[q]; // exact: a power of two
    if (!(std::fabs(quotient) < fixedpoint::two_to_the_63)) {
      return false;
    }
    raw = std::llrint(quotient);
    return true;
  }

  std::array<SummedQuantity, K> quantities_;
  std::array<double, K> inverse_unit_{};
  std::vector<Total> totals_; // slot-major: quantity q of slot s at s * K + q
  std::vector<Bits> invalid_; // per slot, one bit per quantity (fixed point)
  std::array<std::vector<double>, values_are_totals ? 0 : K> values_;
};

} // namespace revsph
