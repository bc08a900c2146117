#include "dynamics/lcp/boxed_pivoting.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tumble::lcp {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}

BoxedPivoting::BoxedPivoting(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                             const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                             const DantzigSettings& settings) {
  reset(A, b, lo, hi, settings);
}

void BoxedPivoting::reset(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const Eigen::VectorXd& lo,
                          const Eigen::VectorXd& hi, const DantzigSettings& settings) {
  A_ = &A, b_ = &b, lo_ = &lo, hi_ = &hi, settings_ = &settings;
  const int n = static_cast<int>(b.size());
  // unprocessed variables wait at the feasible value nearest 0 (0 for contacts and friction)
  f_ = Eigen::VectorXd::Zero(n).cwiseMax(lo).cwiseMin(hi);
  // A f + b without the product's temporary (the same sums: the product is evaluated alone first)
  w_.noalias() = A * f_;
  w_ += b;
  pivots_ = 0;
  delta_ = 0;
  dependent_ = false;
  set_.assign(n, Set::Unprocessed);
  excluded_.assign(n, 0);
  factor_.reset(n);
  y_.resize(n);
  dfC_.resize(n);
  wScale_ = n > 0 ? std::max(A.diagonal().maxCoeff(), std::numeric_limits<double>::min()) : 1.0;
}

bool BoxedPivoting::seed(const std::vector<int>& clamped_guess, const Eigen::VectorXd& guess_f) {
  const int n = static_cast<int>(f_.size());
  for (int i = 0; i < n; ++i) f_[i] = std::clamp(guess_f[i], lo()[i], hi()[i]);
  for (int i : clamped_guess)
    if (lo()[i] < hi()[i] && factor_.add(A(), i, settings().dependence_tolerance)) set_[i] = Set::Clamped;
  const auto& C = factor_.members();
  const int k = factor_.size();
  // A_CC f_C = -(b_C + A_CN f_N): with f_C zeroed, w_C is the right-hand side's negative.
  for (int i : C) f_[i] = 0;
  w_.noalias() = A() * f_;
  w_ += b();
  auto x = y_.head(k);
  for (int r = 0; r < k; ++r) x[r] = -w_[C[r]];
  factor_.solveInPlace(x);
  bool inside = x.allFinite();
  for (int r = 0; r < k && inside; ++r) inside = x[r] >= lo()[C[r]] && x[r] <= hi()[C[r]];
  if (!inside) {
    reset(A(), b(), lo(), hi(), settings());
    return false;
  }
  for (int r = 0; r < k; ++r) f_[C[r]] = x[r];
  w_.noalias() = A() * f_;
  w_ += b();
  for (int i : C) w_[i] = 0;
  return true;
}

LcpStatus BoxedPivoting::run(const std::vector<int>& order, int budget) {
  for (int d : order) {
    if (set_[d] != Set::Unprocessed) continue;   // clamped by seed()
    const LcpStatus s = drive(d, budget);
    if (s != LcpStatus::Solved) return s;
  }
  // Repair: a variable kept out of Clamped as dependent (Zero, or excluded during a drive) may have
  // drifted once the clamped set changed. Drive it again from where it is; one sweep suffices in
  // practice, and each drive is bounded by the same budget.
  for (int i = 0; i < static_cast<int>(set_.size()); ++i) {
    if (set_[i] == Set::Clamped || set_[i] == Set::Fixed || !violates(i)) continue;
    set_[i] = Set::Unprocessed;
    const LcpStatus s = drive(i, budget);
    if (s != LcpStatus::Solved) return s;
  }
  refine();
  return LcpStatus::Solved;
}

// Size of the terms whose cancellation gives w_i: the rounding floor of w_i.
double BoxedPivoting::scaleOf(int i) const {
  return std::abs(b()[i]) + A().col(i).cwiseAbs().dot(f_.cwiseAbs());
}

bool BoxedPivoting::violates(int i) const {
  const double wi = A().col(i).dot(f_) + b()[i];  // A symmetric: column i is row i
  const double tol = settings().residual_tolerance * scaleOf(i);
  if (f_[i] <= lo()[i] && wi >= -tol) return false;
  if (f_[i] >= hi()[i] && wi <= tol) return false;
  return std::abs(wi) > tol;
}

// A variable whose condition already holds when its turn comes is placed without a pivot.
bool BoxedPivoting::settle(int d) {
  w_[d] = A().col(d).dot(f_) + b()[d];
  const double tol = settings().residual_tolerance * scaleOf(d);
  if (lo()[d] == hi()[d]) {
    set_[d] = Set::Fixed;
  } else if (f_[d] <= lo()[d] && w_[d] >= -tol) {
    set_[d] = Set::Lower;
  } else if (f_[d] >= hi()[d] && w_[d] <= tol) {
    set_[d] = Set::Upper;
  } else if (f_[d] > lo()[d] && f_[d] < hi()[d] && std::abs(w_[d]) <= tol) {
    // interior with w = 0: clamp it, or hold it as Zero if it is redundant
    set_[d] = factor_.add(A(), d, settings().dependence_tolerance) ? Set::Clamped : Set::Zero;
    if (set_[d] == Set::Clamped) w_[d] = 0;
  } else {
    return false;
  }
  return true;
}

// d depends on the clamped set and no pivot can change w_d. A consistent redundant system has
// w_d = 0 there, but only to the accuracy of A and b themselves (b is often the small difference of
// large terms), which can exceed the rounding floor used by settle(); accept d at its bound, or as
// Zero inside its box, when |w_d| is within that accuracy.
bool BoxedPivoting::acceptDependent(int d) {
  const double wd = A().col(d).dot(f_) + b()[d];
  if (std::abs(wd) > settings().consistency_tolerance * scaleOf(d)) return false;
  w_[d] = wd;
  if (f_[d] <= lo()[d]) set_[d] = Set::Lower;
  else if (f_[d] >= hi()[d]) set_[d] = Set::Upper;
  else set_[d] = Set::Zero;
  return true;
}

LcpStatus BoxedPivoting::drive(int d, int budget) {
  if (settle(d)) return LcpStatus::Solved;
  const double s = w_[d] < 0 ? 1.0 : -1.0;
  std::fill(excluded_.begin(), excluded_.end(), 0);
  for (;;) {
    if (pivots_ >= budget) return LcpStatus::MaxIterations;
    direction(d, s);
    Blocker blk = ratioTest(d, s);
    if (blk.kind == Block::None && dependent_) {
      if (acceptDependent(d)) return LcpStatus::Solved;
      // nearly but not exactly redundant, and nothing else can stop the load shift: follow the
      // true (tiny) rate of w_d rather than declare the problem infeasible
      dependent_ = !(delta_ > 0);
      if (!dependent_) blk = ratioTest(d, s);
    }
    if (blk.kind == Block::None) return LcpStatus::Failed;  // unbounded ray: infeasible LCP
    step(d, s, blk.t);
    ++pivots_;
    if (apply(blk, d, s)) return LcpStatus::Solved;
    // a pivot elsewhere can leave w_d at 0 to rounding (rows of d and the pivot dependent, so both
    // reach 0 together): then d is done, though no ratio was exactly its own
    if (settle(d)) return LcpStatus::Solved;
  }
}

// Δf_C = −A_CC⁻¹ A_Cd s and Δw = A_{:,C} Δf_C + A_{:,d} s, per unit step.
void BoxedPivoting::direction(int d, double s) {
  delta_ = factor_.schur(A(), d, y_);
  // Baraff's observation (1994): with A PSD, A_CC x = −A_Cd is consistent even when d depends on C;
  // then s_d = 0 and w_d does not move while f_d shifts load among the clamped contacts.
  dependent_ = !(delta_ > settings().dependence_tolerance * A()(d, d));
  factor_.backSolve(y_);
  const auto& C = factor_.members();
  const int k = static_cast<int>(C.size());
  dfC_.head(k) = s * y_.head(k);
  // Δw is needed only where the ratio test looks (Lower, Upper, Zero) and at d: Δw_C = 0 by
  // construction, and unprocessed variables get a fresh w when their turn comes (settle). Row i
  // of A_{:,C} is column i restricted to C (A symmetric), a contiguous-column gather.
  dw_.setZero(A().rows());
  for (int i = 0; i < static_cast<int>(set_.size()); ++i) {
    if (i != d && set_[i] != Set::Lower && set_[i] != Set::Upper && set_[i] != Set::Zero) continue;
    dw_[i] = s * A()(i, d) + (C.empty() ? 0.0 : clampedDot(i));
  }
}

// Row i of A_{:,C} times Δf_C: A(C[0], i) Δf_0 + A(C[1], i) Δf_1 + ..., summed in that order
// (what Eigen's dot over an indexed view does, without the copy of C such a view takes per row).
double BoxedPivoting::clampedDot(int i) const {
  const auto& C = factor_.members();
  const double* column = A().col(i).data();
  double sum = column[C[0]] * dfC_[0];
  for (std::size_t r = 1; r < C.size(); ++r) sum += column[C[r]] * dfC_[static_cast<Eigen::Index>(r)];
  return sum;
}

// The largest |Δf| over the clamped set: the scale of the ratio tests' noise floors.
double BoxedPivoting::directionNorm() const { return dfC_.head(factor_.size()).lpNorm<Eigen::Infinity>(); }

BoxedPivoting::Blocker BoxedPivoting::ratioTest(int d, double s) const {
  Blocker best;
  best.t = kInf;
  // the drive completes when w_d reaches 0 (rate s·delta toward 0), or f_d its bound
  if (!dependent_) best = {Block::DriveDone, d, std::max(0.0, -s * w_[d]) / delta_};
  const double toBound = s > 0 ? hi()[d] - f_[d] : f_[d] - lo()[d];
  if (toBound < best.t) best = {Block::DriveBound, d, toBound};
  ratioTestClamped(best);
  // when d depends on C, A Δf = 0 exactly (Δfᵀ A Δf = s·Δw_d + Δf_C·Δw_C = 0 and A is PSD), so no
  // w moves and only clamped forces can block; skipping the others avoids pivoting on rounding noise
  if (!dependent_) ratioTestOthers(best);
  return best;
}

void BoxedPivoting::ratioTestClamped(Blocker& best) const {
  const auto& C = factor_.members();
  const double tol = settings().pivot_tolerance * std::max(1.0, directionNorm());
  for (int r = 0; r < static_cast<int>(C.size()); ++r) {
    const int i = C[r];
    double t = kInf;
    if (dfC_[r] < -tol) t = std::max(0.0, f_[i] - lo()[i]) / -dfC_[r];
    if (dfC_[r] > tol) t = std::max(0.0, hi()[i] - f_[i]) / dfC_[r];
    if (t < best.t) best = {Block::LeaveClamped, r, t};
  }
}

void BoxedPivoting::ratioTestOthers(Blocker& best) const {
  const double tol = settings().pivot_tolerance * wScale_ * std::max(1.0, directionNorm());
  for (int i = 0; i < static_cast<int>(set_.size()); ++i) {
    if (excluded_[i]) continue;
    double t = kInf;
    switch (set_[i]) {
      case Set::Lower: if (dw_[i] < -tol) t = std::max(0.0, w_[i]) / -dw_[i]; break;
      case Set::Upper: if (dw_[i] > tol) t = std::max(0.0, -w_[i]) / dw_[i]; break;
      case Set::Zero: if (std::abs(dw_[i]) > tol) t = 0; break;
      default: break;
    }
    if (t < best.t) best = {Block::JoinClamped, i, t};
  }
}

void BoxedPivoting::step(int d, double s, double t) {
  if (t == 0) return;
  const auto& C = factor_.members();
  f_[d] += s * t;
  for (int r = 0; r < static_cast<int>(C.size()); ++r) f_[C[r]] += t * dfC_[r];
  w_ += t * dw_;  // exact for d and the bound sets; Clamped w stays 0, Unprocessed w goes stale
}

void BoxedPivoting::placeAtBound(int i, bool upper) {
  f_[i] = upper ? hi()[i] : lo()[i];
  set_[i] = upper ? Set::Upper : Set::Lower;
}

// Moves the blocking variable to its new set; returns true when the drive of d is complete.
bool BoxedPivoting::apply(const Blocker& blk, int d, double s) {
  switch (blk.kind) {
    case Block::DriveDone:
      w_[d] = 0;
      // delta_ passed the same test, so this succeeds; if rounding says otherwise, d is redundant
      set_[d] = factor_.add(A(), d, settings().dependence_tolerance) ? Set::Clamped : Set::Zero;
      return true;
    case Block::DriveBound:
      placeAtBound(d, s > 0);
      return true;
    case Block::LeaveClamped: {
      const int i = factor_.members()[blk.index];
      placeAtBound(i, dfC_[blk.index] > 0);
      factor_.remove(blk.index);
      return false;
    }
    case Block::JoinClamped:
      w_[blk.index] = 0;
      if (factor_.add(A(), blk.index, settings().dependence_tolerance)) set_[blk.index] = Set::Clamped;
      else excluded_[blk.index] = 1;  // redundant: w stays 0 at its bound; see ratioTest
      return false;
    case Block::None: break;
  }
  return true;
}

// One step of iterative refinement on the clamped set: the incremental updates leave w_C at
// rounding times the number of pivots; solving A_CC Δf_C = −w_C with the factor brings it back to
// the rounding of a single solve.
void BoxedPivoting::refine() {
  const auto& C = factor_.members();
  if (C.empty()) return;
  refined_w_.noalias() = A() * f_;
  refined_w_ += b();
  auto r = y_.head(static_cast<Eigen::Index>(C.size()));
  for (int k = 0; k < static_cast<int>(C.size()); ++k) r[k] = refined_w_[C[k]];
  factor_.solveInPlace(r);
  for (int k = 0; k < static_cast<int>(C.size()); ++k)
    f_[C[k]] = std::clamp(f_[C[k]] - r[k], lo()[C[k]], hi()[C[k]]);
}

}  // namespace tumble::lcp
