// The pivoting engine behind solveDantzig for one boxed LCP with fixed bounds (internal header).
//
// Variables are driven into complementarity one at a time (Baraff 1994 §5; Cottle–Dantzig). Every
// processed variable sits in one set:
//   Clamped  lo < f < hi (or at a bound, degenerate), w = 0 — held by the Cholesky factor of A_CC
//   Lower    f = lo, w ≥ 0           Upper   f = hi, w ≤ 0
//   Zero     lo < f < hi, w = 0 but linearly dependent on Clamped, so w stays 0 without being held
//   Fixed    lo = hi
// Driving d moves f_d in the direction that brings w_d toward 0 (s = −sign w_d), with the clamped
// variables following so that w_C stays 0:  A_CC Δf_C = −A_Cd s  (one solve with the factor),
// Δw = A_{:,C} Δf_C + A_{:,d} s. The ratio test finds the largest step keeping every processed
// variable's condition; the variable that blocks changes set (a pivot) and the drive continues until
// w_d = 0 (d joins Clamped) or f_d reaches a bound.
#pragma once

#include "dynamics/lcp/clamped_factor.h"
#include "dynamics/lcp/dantzig_solver.h"

#include <cstdint>
#include <vector>

namespace tumble::lcp {

class BoxedPivoting {
public:
  BoxedPivoting() = default;
  BoxedPivoting(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const Eigen::VectorXd& lo,
                const Eigen::VectorXd& hi, const DantzigSettings& settings);
  // Starts a new problem (the arguments must outlive the solve), reusing the buffers of the last:
  // one of the same size allocates nothing.
  void reset(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const Eigen::VectorXd& lo,
             const Eigen::VectorXd& hi, const DantzigSettings& settings);
  // Starts from a guess of the clamped set (an earlier friction pass's, whose bounds were close):
  // its members are clamped at once, their forces solved with every other variable at `guess_f`
  // moved into its bounds. Returns false, leaving the engine as reset() does, if a guessed member's
  // force comes out outside its bounds; then the drives start from nothing.
  bool seed(const std::vector<int>& clamped_guess, const Eigen::VectorXd& guess_f);
  // Drives the variables in `order` (each once, unless seed() clamped it), then repairs any that
  // drifted; stops after `budget` pivots.
  LcpStatus run(const std::vector<int>& order, int budget);
  // The clamped set, in the factor's order.
  const std::vector<int>& clamped() const { return factor_.members(); }
  const Eigen::VectorXd& f() const { return f_; }
  int pivots() const { return pivots_; }

private:
  enum class Set : std::uint8_t { Unprocessed, Clamped, Lower, Upper, Zero, Fixed };
  enum class Block : std::uint8_t { None, DriveDone, DriveBound, LeaveClamped, JoinClamped };
  struct Blocker {
    Block kind = Block::None;
    int index = -1;  // variable (JoinClamped) or position in the factor (LeaveClamped)
    double t = 0;
  };

  bool settle(int d);
  LcpStatus drive(int d, int budget);
  void direction(int d, double s);
  double clampedDot(int i) const;
  double directionNorm() const;
  Blocker ratioTest(int d, double s) const;
  void ratioTestClamped(Blocker& best) const;
  void ratioTestOthers(Blocker& best) const;
  void step(int d, double s, double t);
  bool apply(const Blocker& blk, int d, double s);
  void placeAtBound(int i, bool upper);
  bool acceptDependent(int d);
  bool violates(int i) const;
  void refine();
  double scaleOf(int i) const;

  // The problem, as set by reset (pointers so that one engine can serve problem after problem).
  const Eigen::MatrixXd& A() const { return *A_; }
  const Eigen::VectorXd& b() const { return *b_; }
  const Eigen::VectorXd& lo() const { return *lo_; }
  const Eigen::VectorXd& hi() const { return *hi_; }
  const DantzigSettings& settings() const { return *settings_; }
  const Eigen::MatrixXd* A_ = nullptr;
  const Eigen::VectorXd* b_ = nullptr;
  const Eigen::VectorXd* lo_ = nullptr;
  const Eigen::VectorXd* hi_ = nullptr;
  const DantzigSettings* settings_ = nullptr;
  Eigen::VectorXd f_, w_;
  std::vector<Set> set_;
  std::vector<char> excluded_;   // dependent variables that cannot join Clamped during this drive
  ClampedFactor factor_;
  // Direction per unit step: Δf over members() (the first size() entries of dfC_), Δw over all.
  // Sized once for n variables: a pivot must not allocate.
  Eigen::VectorXd dfC_, dw_;
  Eigen::VectorXd y_;            // the Schur solve's y (ClampedFactor::schur)
  Eigen::VectorXd refined_w_;    // refine()'s A f + b
  double delta_ = 0;             // Schur complement of d: dw_d = s·delta_
  bool dependent_ = false;       // d is a combination of Clamped: w does not move along the drive
  double wScale_ = 1;            // max_i A_ii: scale for the Δw noise floor
  int pivots_ = 0;
};

}  // namespace tumble::lcp
