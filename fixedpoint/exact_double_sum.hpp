#pragma once
// An order-independent sum of doubles (docs/design/distributed.md, piece 3), for the energies and
// diagnostics that are sums over particles: the same bits whatever the order of the terms, the
// thread or the process that adds them.
//
// Every finite double is an integer multiple of 2^-1074, so each term is added exactly into one
// wide integer (Boost.Multiprecision's fixed-width cpp_int: 2 240 bits hold any double times
// 2^1074 with room for 2^64 terms), and the total is rounded once to the nearest double (ties to
// even). The result is the correctly rounded
// sum of the multiset of terms: exact where that fits a double (e.g. 1 + 1e-300 - 1 = 1e-300).

#include <boost/multiprecision/cpp_int.hpp>

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
  const Wide& units() const { return total_; }
  bool finite() const { return finite_; }
  static ExactDoubleSum from_units(const Wide& units, bool finite) {
    ExactDoubleSum sum;
    sum.total_ = units;
    sum.finite_ = finite;
    return sum;
  }

private:
  Wide total_ = 0;
  bool finite_ = true;
};

} // namespace revsph::fixedpoint
