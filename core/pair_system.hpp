#pragma once
// A symmetric positive-definite linear system over the pairs of a SlotLayout, M_ij = f(r_ij)
// (core/pair_matrix.hpp), solved by conjugate gradients: paper 4's implicit volume, W V = 1
// (eq. 26), and its pressure solve W y = p (eq. 45). The first `unknowns` carriers (canonical
// order) are solved for; the rest keep given values, which enter the right-hand side
// (M_uu x_u = b - M_uh x_h). A fixed zero start and a fixed tolerance make the solution a function
// of the positions alone: the same bits for any thread count and cell size.

#include "core/pair_matrix.hpp"
#include "core/slot_layout.hpp"

#include <Eigen/IterativeLinearSolvers>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <stdexcept>

namespace revsph {

class PairSystem {
public:
  struct Settings {
    double tolerance = 1e-12; // relative residual
    int max_iterations = 5000;
  };

  // Builds M over the layout's carriers and prepares the solver for the block of the first
  // `unknowns` of them.
  template <int D, class Entry>
  void assemble(const SlotLayout<D>& layout, const Entry& f, std::size_t unknowns,
                const Settings& settings) {
    if (layout.exchanges_ghost_sums()) {
      // Each process would solve its own rows alone: not the whole system's answer.
      throw std::logic_error("a pair system (conjugate gradients over the pairs) is not solved "
                             "across processes yet (docs/design/distributed.md): run it on one "
                             "process");
    }
    fill_pair_matrix<D>(layout, f, matrix_);
    const auto u = static_cast<Eigen::Index>(unknowns);
    block_ = matrix_.topLeftCorner(u, u);
    settings_ = settings;
  }

  std::size_t carriers() const { return static_cast<std::size_t>(matrix_.rows()); }
  std::size_t unknowns() const { return static_cast<std::size_t>(block_.rows()); }

  // x over every carrier: its held entries (after the unknowns) are read, the unknowns solved
  // from M x = b on their rows (b: one entry per unknown). False if the solve did not converge.
  bool solve_with_held(std::span<const double> b, std::span<double> x) {
    const Eigen::Index n = matrix_.rows();
    const Eigen::Index u = block_.rows();
    const Eigen::Map<const Eigen::VectorXd> held(x.data() + u, n - u);
    const Eigen::VectorXd right_side =
        Eigen::Map<const Eigen::VectorXd>(b.data(), u) - matrix_.topRightCorner(u, n - u) * held;
    return solve_block(right_side, x);
  }
  // The unknowns alone from M_uu x = b (the held entries taken as zero).
  bool solve_unknowns(std::span<const double> b, std::span<double> x) {
    return solve_block(Eigen::Map<const Eigen::VectorXd>(b.data(), block_.rows()), x);
  }

  // max over the unknowns' rows of |(M x)_i - b_i|, x over every carrier: how well x solves the
  // system.
  double max_residual(std::span<const double> x, std::span<const double> b) const {
    const Eigen::Index u = block_.rows();
    const Eigen::VectorXd product =
        matrix_ * Eigen::Map<const Eigen::VectorXd>(x.data(), matrix_.cols());
    return (product.head(u) - Eigen::Map<const Eigen::VectorXd>(b.data(), u)).cwiseAbs().maxCoeff();
  }

  // Of the last solve.
  int iterations() const { return iterations_; }
  double error() const { return error_; }

private:
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

  PairMatrix matrix_, block_;
  Settings settings_;
  int iterations_ = 0;
  double error_ = 0.0;
};

} // namespace revsph
