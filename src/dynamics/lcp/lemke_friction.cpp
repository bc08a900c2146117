#include "dynamics/lcp/lemke_friction.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace tumble::lcp {

namespace {

bool plainRow(const LcpProblem& p, int i) {
  return !p.isFriction(i) && p.lo[i] == 0 && std::isinf(p.hi[i]) && p.hi[i] > 0;
}

// The complementarity form of the header: M z + q = w >= 0, z >= 0, z'w = 0 with z = [the plain
// rows' f; beta along each edge direction of the friction pyramids; lambda per pyramid]. A
// contact with two friction rows (tangents t1, t2, each bounded by mu f_n) has the square
// pyramid |f_1|, |f_2| <= mu f_n, the cone of the four edges t1 +- t2, t1 -+ t2 scaled by mu f_n:
// f_1 = beta_1 + beta_2 - beta_3 - beta_4 and the like, with beta_1 + ... + beta_4 <= mu f_n.
// One friction row alone has the two edges +-t. This is Anitescu and Potra's form (one lambda
// per contact, the edges summing to at most mu f_n), for which Lemke's method is proved to work.
struct Expanded {
  Eigen::MatrixXd M;
  Eigen::VectorXd q;
  std::vector<int> plain;                                  // original row of each normal variable
  std::vector<std::array<std::pair<int, double>, 2>> edge; // (row, sign) pairs of each edge (sign 0: none)
  Eigen::VectorXd scale;                                   // z = scale * (the scaled problem's z)
};

void expand(const LcpProblem& p, Expanded& e) {
  e.plain.clear();
  e.edge.clear();
  std::vector<int> slot(p.size(), -1);
  for (int i = 0; i < p.size(); ++i)
    if (!p.isFriction(i)) slot[i] = static_cast<int>(e.plain.size()), e.plain.push_back(i);
  const int nn = static_cast<int>(e.plain.size());
  // The friction rows of each normal, in order.
  std::vector<std::array<int, 2>> rows_of(nn, {-1, -1});
  for (int i = 0; i < p.size(); ++i) {
    if (!p.isFriction(i)) continue;
    std::array<int, 2>& r = rows_of[slot[p.friction_of[i]]];
    (r[0] < 0 ? r[0] : r[1]) = i;
  }
  std::vector<int> pyramid_of;   // the normal variable of each edge
  for (int a = 0; a < nn; ++a) {
    const auto [r1, r2] = rows_of[a];
    if (r1 < 0) continue;
    for (double s1 : {1.0, -1.0}) {
      if (r2 < 0) {
        e.edge.push_back({{{r1, s1}, {-1, 0.0}}});
        pyramid_of.push_back(a);
        continue;
      }
      for (double s2 : {1.0, -1.0}) {
        e.edge.push_back({{{r1, s1}, {r2, s2}}});
        pyramid_of.push_back(a);
      }
    }
  }
  std::vector<int> lambda_of(nn, -1);
  int nl = 0;
  for (int a = 0; a < nn; ++a)
    if (rows_of[a][0] >= 0) lambda_of[a] = nl++;
  const int nd = static_cast<int>(e.edge.size());
  const int n = nn + nd + nl, L = nn + nd;
  e.M.setZero(n, n);
  e.q.setZero(n);
  // The first nn + nd variables are directions in the original rows: a normal's unit row, an
  // edge's two signed rows. M there is (direction x)' A (direction y), q is (direction x)' b.
  auto terms = [&](int x) -> std::array<std::pair<int, double>, 2> {
    if (x < nn) return {{{e.plain[x], 1.0}, {-1, 0.0}}};
    return e.edge[x - nn];
  };
  for (int x = 0; x < L; ++x) {
    const auto tx = terms(x);
    for (const auto& [r, s] : tx)
      if (r >= 0) e.q[x] += s * p.b[r];
    for (int y = 0; y < L; ++y) {
      const auto ty = terms(y);
      double m = 0;
      for (const auto& [r, s] : tx)
        for (const auto& [c, t] : ty)
          if (r >= 0 && c >= 0) m += s * t * p.A(r, c);
      e.M(x, y) = m;
    }
  }
  for (int j = 0; j < nd; ++j) {
    const int a = pyramid_of[j];
    e.M(nn + j, L + lambda_of[a]) = 1;    // the edge's speed plus the sliding speed >= 0
    e.M(L + lambda_of[a], nn + j) = -1;   // mu f_n less the edges' sum >= 0
  }
  for (int a = 0; a < nn; ++a)
    if (lambda_of[a] >= 0) e.M(L + lambda_of[a], a) = p.mu[rows_of[a][0]];
  // Scaled to unit diagonal: z = S z', w' = S w, M' = S M S (a positive diagonal S keeps M
  // copositive and maps answers one to one). A light shard's rows beside a heavy one's span three
  // decades of diagonal, and the bases such spreads give lose digits the ties need. lambda is
  // scaled by the inverse of its edges' mean scale, so that its coupling to them is near 1.
  e.scale.setOnes(n);
  for (int x = 0; x < L; ++x)
    if (e.M(x, x) > 0) e.scale[x] = 1 / std::sqrt(e.M(x, x));
  Eigen::VectorXd edge_scale = Eigen::VectorXd::Zero(nl), edges = Eigen::VectorXd::Zero(nl);
  for (int j = 0; j < nd; ++j) edge_scale[lambda_of[pyramid_of[j]]] += e.scale[nn + j], edges[lambda_of[pyramid_of[j]]] += 1;
  for (int l = 0; l < nl; ++l) e.scale[L + l] = edges[l] / edge_scale[l];
  e.M = e.scale.asDiagonal() * e.M * e.scale.asDiagonal();
  e.q = e.scale.cwiseProduct(e.q);
}

// Lemke's method on w = M z + q with the covering vector of ones, lexicographic ratio test
// (which rules out cycling on the degenerate problems contacts give: a resting contact has
// q_i = 0). Revised form: the basis inverse B^-1 of the columns of [I, -M, -1] is kept and
// updated by each pivot, the entering column and the right-hand side are B^-1 times the
// original ones, and the tie-break reads B^-1's rows. Updating B^-1 in place accumulates
// rounding (a path of 128 pivots on two bodies with twelve contacts ended on a false ray where
// exact arithmetic reached the answer), so every few pivots and before a ray is believed it is
// formed again from the basis by one LU factorisation.
class LemkePath {
 public:
  LemkePath(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, const LemkeSettings& settings)
      : n_(static_cast<int>(q.size())), z0_(2 * n_), settings_(settings), M_(M), q_(q) {
    Binv_.setIdentity(n_, n_);
    rhs_ = q;
    basis_.resize(n_);
    for (int i = 0; i < n_; ++i) basis_[i] = i;   // the w's
  }

  LcpStatus run(Eigen::VectorXd& z, int& pivots) {
    const LcpStatus status = follow(z);
    pivots = pivots_;
    return status;
  }

 private:
  LcpStatus follow(Eigen::VectorXd& z) {
    z.setZero(n_);
    if (n_ == 0 || q_.minCoeff() >= 0) return LcpStatus::Solved;
    // z0 enters at the least q_i: the covering vector lifts every w to >= 0.
    rows_.clear();
    for (int i = 0; i < n_; ++i) rows_.push_back(i);
    ones_ = Eigen::VectorXd::Ones(n_);
    int r = lexicoMin([&](int i, int c) { return c < 0 ? rhs_[i] : Binv_(i, c); }, ones_);
    int leaving = basis_[r];
    enteringColumn(z0_);
    pivot(r, z0_);
    int entering = complement(leaving);
    const int cap = settings_.max_pivots_per_variable * n_ + 100;
    while (leaving != z0_) {
      if (pivots_ >= cap) return LcpStatus::MaxIterations;
      if (pivots_ % refactorEvery() == 0) refactor();
      r = leavingRow(entering);
      if (r < 0) {
        refactor();
        r = leavingRow(entering);
        if (r < 0) return LcpStatus::Failed;   // a ray: no solution from here
      }
      leaving = basis_[r];
      pivot(r, entering);
      entering = complement(leaving);
    }
    refactorAnswer();   // the answer from the basis alone, not from the pivots' rounding
    for (int i = 0; i < n_; ++i)
      if (basis_[i] >= n_ && basis_[i] < z0_) z[basis_[i] - n_] = std::max(rhs_[i], 0.0);
    return LcpStatus::Solved;
  }

  // Pivots between refactorings (each O(n^3) against a pivot's O(n^2)): rounding grows with
  // the pivots since, and the paths contacts give are short (a stack of 8 cubes: 25 pivots).
  int refactorEvery() const { return 16; }

  // The rounding a value of the path carries, as a share of the largest of its kind: B^-1 is
  // formed again every 16 pivots, but the bases of degenerate contact problems are ill
  // conditioned, and a tie that exact arithmetic has was seen split by 3e-11 of the right-hand
  // side's largest entry (the path then left the tie by the wrong row and ended on a false ray;
  // in 6000 random contact problems none did at 1e-10, 27 at 1e-12).
  static constexpr double kNoise = 1e-10;

  int complement(int v) const { return v < n_ ? v + n_ : v - n_; }

  // Column `e` of [I, -M, -1].
  void originalColumn(int e, Eigen::VectorXd& out) const {
    if (e < n_) out = Eigen::VectorXd::Unit(n_, e);
    else if (e < z0_) out = -M_.col(e - n_);
    else out = -Eigen::VectorXd::Ones(n_);
  }

  // d = B^-1 times column `e`.
  void enteringColumn(int e) {
    originalColumn(e, original_);
    d_.noalias() = Binv_ * original_;
  }

  // Pivots on row r with the entering column in d_.
  void pivot(int r, int e) {
    const double pr = d_[r];
    Binv_.row(r) /= pr;
    rhs_[r] /= pr;
    for (int i = 0; i < n_; ++i) {
      if (i == r || d_[i] == 0) continue;
      Binv_.row(i) -= d_[i] * Binv_.row(r);
      rhs_[i] -= d_[i] * rhs_[r];
    }
    basis_[r] = e;
    ++pivots_;
  }

  // The basis's columns, factorised.
  const Eigen::PartialPivLU<Eigen::MatrixXd>& factorBasis() {
    B_.resize(n_, n_);
    for (int i = 0; i < n_; ++i) {
      originalColumn(basis_[i], original_);
      B_.col(i) = original_;
    }
    lu_.compute(B_);
    return lu_;
  }

  // The right-hand side alone from the basis: the path's answer.
  void refactorAnswer() {
    const Eigen::PartialPivLU<Eigen::MatrixXd>& lu = factorBasis();
    original_ = lu.solve(q_);
    if (original_.allFinite()) rhs_ = original_;
  }

  void refactor() {
    const Eigen::PartialPivLU<Eigen::MatrixXd>& lu = factorBasis();
    inverse_ = lu.inverse();
    // A basis singular to rounding (a pivot the tolerance let through): keep the updated inverse.
    if (!inverse_.allFinite()) return;
    Binv_ = inverse_;
    rhs_.noalias() = Binv_ * q_;
  }

  // The row that blocks the entering variable first (its column left in d_), -1 on a ray. Where
  // z0 ties for the least ratio it leaves, and the path ends: in exact arithmetic such a tie is
  // often a true one (several blocking rows reach zero at once), which rounding splits by about
  // 1e-12 of the ratio; a pivot on another row instead can lead the path onto a ray.
  int leavingRow(int e) {
    enteringColumn(e);
    const double column_size = d_.cwiseAbs().maxCoeff();
    rows_.clear();
    for (int i = 0; i < n_; ++i)
      if (d_[i] > settings_.pivot_tolerance * column_size) rows_.push_back(i);
    if (rows_.empty()) return -1;
    double least = std::numeric_limits<double>::infinity();
    for (int i : rows_) least = std::min(least, rhs_[i] / d_[i]);
    const double noise = kNoise * rhs_.cwiseAbs().maxCoeff();   // as in lexicoMin
    for (int i : rows_)
      if (basis_[i] == z0_ && rhs_[i] / d_[i] <= least + settings_.tie_tolerance * std::abs(least) + noise / d_[i])
        return i;
    return lexicoMin([&](int i, int c) { return c < 0 ? rhs_[i] : Binv_(i, c); }, d_);
  }

  // Among rows_, those whose ratio v_i / d_i is least (v: column -1 the right-hand side, then each
  // column of B^-1 in turn), until one is left. Ratios tie within tie_tolerance of the least, or
  // within what rounding of v (kNoise of the column's largest |v|) makes of them: a degenerate
  // row whose v is 0 in exact arithmetic reads +-1e-17.
  template <class Value>
  int lexicoMin(Value value, const Eigen::VectorXd& d) {
    for (int c = -1; rows_.size() > 1 && c < n_; ++c) {
      double scale = 0;
      for (int i = 0; i < n_; ++i) scale = std::max(scale, std::abs(value(i, c)));
      double least = std::numeric_limits<double>::infinity();
      for (int i : rows_) least = std::min(least, value(i, c) / d[i]);
      next_.clear();
      for (int i : rows_)
        if (value(i, c) / d[i] <= least + settings_.tie_tolerance * std::abs(least) + kNoise * scale / d[i])
          next_.push_back(i);
      rows_.swap(next_);
    }
    return rows_.front();
  }

  int n_, z0_;
  const LemkeSettings& settings_;
  const Eigen::MatrixXd& M_;
  const Eigen::VectorXd& q_;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> Binv_;
  Eigen::MatrixXd inverse_, B_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  Eigen::VectorXd rhs_, d_, original_, ones_;
  std::vector<int> basis_, rows_, next_;
  int pivots_ = 0;
};

}  // namespace

bool lemkeCovers(const LcpProblem& p) {
  std::vector<int> count(p.size(), 0), first(p.size(), -1);
  for (int i = 0; i < p.size(); ++i) {
    if (p.isFriction(i)) {
      const int k = p.friction_of[i];
      if (k < 0 || k >= p.size() || !plainRow(p, k) || !(p.mu[i] >= 0)) return false;
      if (++count[k] > 2 || (first[k] >= 0 && p.mu[first[k]] != p.mu[i])) return false;
      first[k] = i;
    } else if (!plainRow(p, i)) {
      return false;
    }
  }
  return true;
}

void solveLemkeFriction(const LcpProblem& p, const LemkeSettings& settings, LcpResult& r) {
  r.f.setZero(p.size());
  r.iterations = 0;
  r.friction_passes = 0;
  r.status = LcpStatus::Failed;
  if (!lemkeCovers(p) || !p.A.allFinite() || !p.b.allFinite()) {
    r.w = p.b;
    r.residual = measureResidual(p, r.f, r.w);
    return;
  }
  thread_local Expanded e;
  thread_local Eigen::VectorXd z;
  thread_local Eigen::MatrixXd regularised;
  expand(p, e);
  const int nn = static_cast<int>(e.plain.size()), forces = nn + static_cast<int>(e.edge.size());
  // The answer of the path on M, into r; whether it is exact.
  auto answer = [&](const Eigen::MatrixXd& M) {
    int pivots = 0;
    const LcpStatus status = LemkePath(M, e.q, settings).run(z, pivots);
    r.iterations += pivots;
    z = z.cwiseProduct(e.scale);
    r.f.setZero(p.size());
    for (int a = 0; a < nn; ++a) r.f[e.plain[a]] = z[a];
    for (std::size_t j = 0; j < e.edge.size(); ++j)
      for (const auto& [row, sign] : e.edge[j])
        if (row >= 0) r.f[row] += sign * z[nn + j];
    r.w.noalias() = p.A * r.f;
    r.w += p.b;
    r.residual = measureResidual(p, r.f, r.w);
    // Exact when what is left is rounding of the terms that cancel in w.
    const double terms = p.b.lpNorm<Eigen::Infinity>() + p.A.lpNorm<Eigen::Infinity>() * r.f.lpNorm<Eigen::Infinity>();
    const bool exact = std::max(r.residual.complementarity, r.residual.bounds) <= 1e-9 * (terms + 1e-300);
    r.status = status == LcpStatus::Solved && !exact ? LcpStatus::MaxIterations : status;
    return r.status == LcpStatus::Solved;
  };
  if (answer(e.M) || settings.regularisation <= 0) return;
  // Where rounding defeated the path (a tower of blocks, each face four coplanar corners: the
  // edges' and the redundant normals' rows make most bases near singular), the path again on
  // M + eps I over the impulses: a unique answer, within eps of the force of being exact.
  regularised = e.M;
  for (int x = 0; x < forces; ++x) regularised(x, x) += settings.regularisation;
  answer(regularised);
  if (r.status == LcpStatus::Solved) r.status = LcpStatus::MaxIterations;   // near, not exact
}

}  // namespace tumble::lcp
