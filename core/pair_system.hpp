#pragma once
// A symmetric positive-definite linear system over the pairs of a SlotLayout, M_ij = f(r_ij)
// (core/pair_matrix.hpp), solved by conjugate gradients: paper 4's implicit volume, W V = 1
// (eq. 26), and its pressure solve W y = p (eq. 45). The first `unknowns` carriers (canonical
// order) are solved for; the rest keep given values, which enter the right-hand side
// (M_uu x_u = b - M_uh x_h). A fixed zero start and a fixed tolerance make the solution a function
// of the positions alone: the same bits for any thread count and cell size.
//
// In a distributed run (docs/design/distributed.md) each process sends its own carriers' rows,
// numbered as in a one-process run (set after set, each in its global order), to process 0,
// which solves the whole system exactly as one process would and sends the solution back: the
// same bits for any number of processes. The unknowns are then the leading sets' particles,
// own and ghost.

#include "core/distributed/on_first_process.hpp"
#include "core/distributed/processes.hpp"
#include "core/global_totals.hpp"
#include "core/pair_matrix.hpp"
#include "core/slot_layout.hpp"

#include <Eigen/IterativeLinearSolvers>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

namespace revsph {

class PairSystem {
public:
  struct Settings {
    double tolerance = 1e-12; // relative residual
    int max_iterations = 5000;
  };

  // Builds M over the layout's carriers and prepares the solver for the block of the first
  // `unknowns` of them (in a distributed run: of this process's own carriers, the leading sets';
  // collective).
  template <int D, class Entry>
  void assemble(const SlotLayout<D>& layout, const Entry& f, std::size_t unknowns,
                const Settings& settings) {
    settings_ = settings;
    fill_pair_matrix<D>(layout, f, matrix_);
    gathered_ = layout.exchanges_ghost_sums();
    if (!gathered_) {
      const auto u = static_cast<Eigen::Index>(unknowns);
      block_ = matrix_.topLeftCorner(u, u);
      total_unknowns_ = unknowns;
      return;
    }
    number_carriers(layout, unknowns);
    gather_matrix(layout.first_carrier(layout.sets().size()));
  }

  // Whether a carrier (of this process: own or ghost) is one of the system's unknowns.
  bool is_unknown(std::size_t carrier) const {
    return gathered_ ? number_[carrier] < total_unknowns_ : carrier < total_unknowns_;
  }

  // x over every carrier: its held entries are read, the unknowns solved from M x = b on their
  // rows (b: one entry per unknown of this process's own). False if the solve did not converge.
  bool solve_with_held(std::span<const double> b, std::span<double> x) { return solve(b, x, true); }
  // The unknowns alone from M_uu x = b (the held entries taken as zero).
  bool solve_unknowns(std::span<const double> b, std::span<double> x) { return solve(b, x, false); }

  // max over the unknowns' rows of |(M x)_i - b_i|, x over every carrier: how well x solves the
  // system (collective in a distributed run; computed there on process 0's whole system, so
  // that the number is the one-process run's).
  RunTotal max_residual(std::span<const double> x, std::span<const double> b) {
    if (!gathered_) {
      return RunTotal::same_on_every_process(residual_of(x, b));
    }
    const Whole whole = gather_vectors(b, x);
    const double local = distributed::process_rank() == 0 ? residual_of(whole.x, whole.b) : 0.0;
    return global_max(local);
  }

  // Of the last solve.
  int iterations() const { return iterations_; }
  double error() const { return error_; }

private:
  struct Entry {
    std::uint64_t row, column;
    double value;
  };
  struct Numbered {
    std::uint64_t number;
    double value;
  };
  struct Outcome {
    double error;
    std::int64_t iterations, converged;
  };
  struct Whole {
    std::vector<double> b, x; // b over the unknowns, x over every carrier (process 0)
  };

  double residual_of(std::span<const double> x, std::span<const double> b) const {
    const Eigen::Index u = block_.rows();
    const PairMatrix& m = gathered_ ? whole_ : matrix_;
    const Eigen::VectorXd product = m * Eigen::Map<const Eigen::VectorXd>(x.data(), m.cols());
    return (product.head(u) - Eigen::Map<const Eigen::VectorXd>(b.data(), u)).cwiseAbs().maxCoeff();
  }

  // Each carrier's number in the one-process order: the sets' totals over every process before
  // its set, plus its global index in the set.
  template <int D>
  void number_carriers(const SlotLayout<D>& layout, std::size_t unknowns) {
    const std::size_t sets = layout.sets().size();
    std::vector<std::uint64_t> first(sets + 1, 0);
    for (std::size_t k = 0; k < sets; ++k) {
      const auto own = static_cast<std::int64_t>(layout.sets()[k].count);
      first[k + 1] = first[k] + static_cast<std::uint64_t>(distributed::sum_over_processes(own));
    }
    total_carriers_ = first[sets];
    total_unknowns_ = static_cast<std::uint64_t>(
        distributed::sum_over_processes(static_cast<std::int64_t>(unknowns)));
    own_unknowns_ = unknowns;
    number_.resize(layout.carrier_count());
    for (std::size_t c = 0; c < number_.size(); ++c) {
      const SetParticle particle = layout.global_particle_of_carrier(c);
      number_[c] = first[particle.set] + particle.index;
    }
  }

  // Process 0's whole matrix from every process's own rows (collective).
  void gather_matrix(std::size_t own_carriers) {
    std::vector<Entry> mine;
    for (Eigen::Index row = 0; row < static_cast<Eigen::Index>(own_carriers); ++row) {
      for (PairMatrix::InnerIterator it(matrix_, row); it; ++it) {
        mine.push_back({number_[static_cast<std::size_t>(row)],
                        number_[static_cast<std::size_t>(it.col())], it.value()});
      }
    }
    own_carriers_ = own_carriers;
    const std::vector<Entry> all = distributed::gathered_on_first(std::span<const Entry>(mine));
    const auto n = static_cast<Eigen::Index>(total_carriers_);
    const auto u = static_cast<Eigen::Index>(total_unknowns_);
    whole_.resize(0, 0);
    block_.resize(0, 0);
    if (distributed::process_rank() != 0) {
      return;
    }
    std::vector<Eigen::Triplet<double, int>> triplets;
    triplets.reserve(all.size());
    for (const Entry& e : all) {
      triplets.emplace_back(static_cast<int>(e.row), static_cast<int>(e.column), e.value);
    }
    whole_.resize(n, n);
    whole_.setFromTriplets(triplets.begin(), triplets.end()); // the one-process matrix
    block_ = whole_.topLeftCorner(u, u);
  }

  // b (over this process's own unknowns) and x (over its own carriers) as the whole run's
  // vectors on process 0 (collective).
  Whole gather_vectors(std::span<const double> b, std::span<const double> x) const {
    std::vector<Numbered> mine;
    mine.reserve(own_carriers_ + own_unknowns_);
    for (std::size_t c = 0; c < own_carriers_; ++c) {
      if ((number_[c] < total_unknowns_) != (c < own_unknowns_)) {
        throw std::logic_error("a distributed pair system's unknowns must be whole leading sets");
      }
      mine.push_back({number_[c], x[c]});
    }
    for (std::size_t c = 0; c < own_unknowns_; ++c) {
      mine.push_back({total_carriers_ + number_[c], b[c]}); // b's entries after x's
    }
    const std::vector<Numbered> all =
        distributed::gathered_on_first(std::span<const Numbered>(mine));
    Whole whole;
    if (distributed::process_rank() == 0) {
      whole.x.assign(total_carriers_, 0.0);
      whole.b.assign(total_unknowns_, 0.0);
      for (const Numbered& n : all) {
        (n.number < total_carriers_ ? whole.x[n.number] : whole.b[n.number - total_carriers_]) =
            n.value;
      }
    }
    return whole;
  }

  bool solve(std::span<const double> b, std::span<double> x, bool with_held) {
    if (!gathered_) {
      return solve_here(b, x, with_held);
    }
    Whole whole = gather_vectors(b, x);
    Outcome outcome{0.0, 0, 0};
    std::vector<double> solution;
    if (distributed::process_rank() == 0) {
      const bool converged = solve_here(whole.b, whole.x, with_held);
      outcome = {error_, iterations_, converged ? 1 : 0};
      solution.assign(whole.x.begin(),
                      whole.x.begin() + static_cast<std::ptrdiff_t>(total_unknowns_));
    }
    const Outcome agreed = distributed::sent_from_first(std::span<const Outcome>(&outcome, 1))[0];
    solution = distributed::sent_from_first(std::span<const double>(solution));
    error_ = agreed.error;
    iterations_ = static_cast<int>(agreed.iterations);
    for (std::size_t c = 0; c < number_.size(); ++c) {
      if (number_[c] < total_unknowns_) {
        x[c] = solution[number_[c]];
      }
    }
    return agreed.converged != 0;
  }

  // The one-process solve over x's whole length (the unknowns first).
  bool solve_here(std::span<const double> b, std::span<double> x, bool with_held) {
    const PairMatrix& m = gathered_ ? whole_ : matrix_;
    const Eigen::Index n = m.rows();
    const Eigen::Index u = block_.rows();
    const Eigen::Map<const Eigen::VectorXd> right(b.data(), u);
    if (!with_held) {
      return solve_block(right, x);
    }
    const Eigen::Map<const Eigen::VectorXd> held(x.data() + u, n - u);
    const Eigen::VectorXd right_side = right - m.topRightCorner(u, n - u) * held;
    return solve_block(right_side, x);
  }

  // The solver is made for each solve (Eigen's is neither copyable nor movable; its Jacobi
  // preconditioner costs one pass over the diagonal).
  template <class RightSide>
  bool solve_block(const RightSide& right_side, std::span<double> x) {
    Eigen::ConjugateGradient<PairMatrix, Eigen::Lower | Eigen::Upper> solver;
    solver.setTolerance(settings_.tolerance);
    solver.setMaxIterations(settings_.max_iterations);
    solver.compute(block_);
    Eigen::Map<Eigen::VectorXd>(x.data(), block_.rows()) = solver.solve(right_side);
    iterations_ = static_cast<int>(solver.iterations());
    error_ = solver.error();
    return solver.info() == Eigen::Success;
  }

  PairMatrix matrix_; // this process's carriers (own and ghost)
  PairMatrix whole_;  // a distributed run's whole system, on process 0
  PairMatrix block_;  // the unknowns' block of the system solved here
  Settings settings_;
  bool gathered_ = false;
  std::vector<std::uint64_t> number_; // each carrier's number in the one-process order
  std::uint64_t total_carriers_ = 0, total_unknowns_ = 0;
  std::size_t own_carriers_ = 0, own_unknowns_ = 0;
  int iterations_ = 0;
  double error_ = 0.0;
};

} // namespace revsph
