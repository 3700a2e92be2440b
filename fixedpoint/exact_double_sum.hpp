#pragma once
// An order-independent sum of doubles (docs/design/distributed.md, piece 3), for the energies and
// diagnostics that are sums over particles: the same bits whatever the order of the terms, the
// thread or the process that adds them.
//
// Every finite double is an integer multiple of 2^-1074, so each term is added exactly into one
// wide integer, and the total is rounded once to the nearest double (ties to even): the correctly
// rounded sum of the multiset of terms, exact where that fits a double (1 + 1e-300 - 1 = 1e-300).
// The wide integer is kept as 70 chunks of 32 bits in int64, a term's 53-bit mantissa landing in
// three of them: 10 ns a term (adding into one 2 240-bit Boost cpp_int took 95 ns; a plain
// double sum 0.8 ns). The chunks have headroom for 2^30 terms and are folded into a fixed-width
// Boost.Multiprecision cpp_int (2 240 bits: any double times 2^1074, room for 2^64 terms) before
// it runs out and when the total is read.

#include <boost/multiprecision/cpp_int.hpp>

#include <array>
#include <cstddef>
#include <cstdint>

namespace revsph::fixedpoint {

class ExactDoubleSum {
public:
  // Adds a term; a non-finite one makes value() NaN.
  void add(double term);
  // Adds another sum's terms (a thread's or a process's part).
  void add(const ExactDoubleSum& other);
  ExactDoubleSum& operator+=(double term) {
    add(term);
    return *this;
  }

  // The total rounded to the nearest double (ties to even); NaN after a non-finite term;
  // +-infinity where the total overflows a double.
  double value() const;

  using Wide = boost::multiprecision::number<boost::multiprecision::cpp_int_backend<
      2240, 2240, boost::multiprecision::signed_magnitude, boost::multiprecision::unchecked, void>>;
  // The total in units of 2^-1074, and whether every term was finite (for sending it elsewhere).
  Wide units() const;
  bool finite() const { return finite_; }
  static ExactDoubleSum from_units(const Wide& units, bool finite) {
    ExactDoubleSum sum;
    sum.folded_ = units;
    sum.finite_ = finite;
    return sum;
  }

  // A fixed-size image of the sum, to send it to another process: the magnitude of units() in
  // 280 little-endian bytes, then its sign and whether every term was finite.
  static constexpr std::size_t image_size = 2240 / 8 + 2;
  using Image = std::array<std::uint8_t, image_size>;
  Image image() const;
  static ExactDoubleSum from_image(const Image& image);

private:
  static constexpr int chunk_bits = 32;
  static constexpr int chunk_count = 70; // 70 x 32 = 2 240 bits
  // Terms added to the chunks since they were last folded; each adds less than 2^32 in magnitude
  // to a chunk, so 2^30 of them stay far inside int64.
  static constexpr std::int64_t terms_before_folding = std::int64_t{1} << 30;

  void fold();

  std::array<std::int64_t, chunk_count> chunks_{};
  std::int64_t pending_ = 0;
  Wide folded_ = 0;
  bool finite_ = true;
};

} // namespace revsph::fixedpoint
