#include "dynamics/baraff/point_impact.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

namespace tumble {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Pieces at most: a turning slip takes a few hundred, each stop a few more; a pathological K
// (nearly singular) is handed back unfinished rather than followed for ever.
constexpr int kMaxPieces = 100000;
// The slip keeps its direction when the part of its rate of change across it is below this share
// of the rate: rounding in a planar impact (whose cross term is exactly 0 up to that) and less.
constexpr double kKeepsDirection = 1e-10;
// A turning slip is followed in pieces over which its direction turns by about this angle (rad),
// each taking the direction of its middle. Against pieces thirty times finer, over 4000 random
// 3-D impacts, the impulse differed by 1.4e-5 of itself on average and 1.7e-3 at worst (where the
// slip nearly stops); a few hundred pieces on average.
constexpr double kTurn = 0.003;
// ... and at most this share of the way to where the slip would stop at its present rate: the
// turning rate grows as the slip shrinks, so a piece may not cross much of the way down.
constexpr double kApproach = 0.5;
// A turning slip slower than this share of the initial relative speed has stopped.
constexpr double kStopped = 1e-10;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// The direction a stopped slip slides on in when holding it would need more than mu: the one s
// (|s| = 1) whose slip grows along itself, K_tn - mu K_tt s = lambda s with lambda > 0, so
// s = (lambda I + mu K_tt)^-1 K_tn. |s(lambda)| falls as lambda grows (K_tt is positive definite):
// from |K_tt^-1 K_tn| / mu > 1 at lambda = 0 to at most 1 at lambda = |K_tn|; one root between.
Eigen::Vector2d slideOnDirection(const Eigen::Matrix2d& Ktt, const Eigen::Vector2d& Ktn, double mu) {
  auto slip = [&](double lambda) {
    return Eigen::Vector2d((lambda * Eigen::Matrix2d::Identity() + mu * Ktt).inverse() * Ktn);
  };
  double lo = 0, hi = Ktn.norm();
  for (int i = 0; i < 200 && hi - lo > 1e-16 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (slip(mid).norm() > 1 ? lo : hi) = mid;
  }
  return slip(hi).normalized();
}

// The normal impulse after which the work W + u_n t + D_n t^2 / 2 has grown by c >= 0, or infinity.
double workReached(double c, double u_n, double D_n) {
  if (c <= 0) return 0;
  const double disc = u_n * u_n + 2 * D_n * c;
  if (disc < 0) return kInf;
  const double denominator = u_n + std::sqrt(disc);   // the stable root: 2c / (u + sqrt(u^2 + 2Dc))
  return denominator > 0 ? 2 * c / denominator : kInf;
}

enum class Event { PieceEnds, SlipStops, CompressionEnds, ImpactEnds };

}  // namespace

PointImpact followPointImpact(const Eigen::Matrix3d& K, const Eigen::Vector3d& u0, double mu, double e,
                              RestitutionLaw law) {
  PointImpact out;
  out.ended = true;
  if (!(u0[0] < 0)) return out;
  out.ended = false;
  const Eigen::Matrix2d Ktt = K.block<2, 2>(1, 1);
  const Eigen::Vector2d Ktn = K.block<2, 1>(1, 0);
  // The tangential impulse per unit normal impulse that keeps a stopped slip stopped, and whether
  // the friction cone holds it; if not, the direction it slides on in.
  const Eigen::Vector2d hold = -(Ktt.inverse() * Ktn);
  const bool sticks = hold.norm() <= mu;
  const Eigen::Vector2d slide_on = mu > 0 && !sticks ? slideOnDirection(Ktt, Ktn, mu) : Eigen::Vector2d::Zero();
  const double stopped = kStopped * u0.norm();

  Eigen::Vector3d u = u0, p = Eigen::Vector3d::Zero();
  double work = 0;
  bool slipping = mu > 0 && u.tail<2>().norm() > stopped, restitution = false;
  double p_end = kInf, work_end = kInf;   // where restitution ends (Poisson, Stronge)
  for (int piece = 1; piece <= kMaxPieces; ++piece) {
    // g: the tangential impulse per unit normal impulse over this piece.
    Eigen::Vector2d g = Eigen::Vector2d::Zero(), rate = Eigen::Vector2d::Zero();
    double planned = kInf;
    bool turning = false;
    const Eigen::Vector2d s = u.tail<2>();
    slipping = slipping && s.norm() > stopped;
    if (mu > 0 && !slipping) {
      g = sticks ? hold : Eigen::Vector2d(-mu * slide_on);
    } else if (slipping) {
      g = -mu * s.normalized();
      rate = Ktn + Ktt * g;
      const double across = std::abs(cross(s.normalized(), rate));   // |s| times its turning rate
      turning = across > kKeepsDirection * rate.norm();
      if (turning) planned = s.norm() * std::min(kTurn / across, kApproach / rate.norm());
    }
    Eigen::Vector3d D;   // du / dp_n over the piece
    double step = kInf;
    Event event = Event::PieceEnds;
    for (int pass = 0; pass < 2; ++pass) {
      if (turning) {
        // The slip turns: a short piece, with the direction the slip has in its middle.
        const Eigen::Vector2d middle = s + 0.5 * planned * rate;
        if (middle.norm() > 0) g = -mu * middle.normalized();
      }
      D = K * Eigen::Vector3d(1, g.x(), g.y());
      step = planned;
      event = Event::PieceEnds;
      // The first pass takes an event before the planned end, the second one at it too (an event
      // that cut the piece to nothing, as at the very end of the impact, must still be taken).
      auto sooner = [&](double t, Event e) {
        if (t >= 0 && (t < step || (pass == 1 && t == step))) step = t, event = e;
      };
      if (slipping && !turning) {
        // A slip that keeps its direction stops where s + D_t t = 0. (A turning one is followed
        // down in pieces that at most halve it: a turning slip may also pass the origin at a
        // distance, its least point no stop.)
        const Eigen::Vector2d d = D.tail<2>();
        if (d.squaredNorm() > 0 && s.dot(d) < 0) sooner(-s.dot(d) / d.squaredNorm(), Event::SlipStops);
      }
      if (!restitution) {
        if (D[0] > 0) sooner(-u[0] / D[0], Event::CompressionEnds);
      } else {
        sooner(law == RestitutionLaw::Poisson ? std::max(p_end - p[0], 0.0)
                                              : workReached(work_end - work, u[0], D[0]),
               Event::ImpactEnds);
        if (D[0] < 0) sooner(-u[0] / D[0], Event::ImpactEnds);   // back to rest along the normal
      }
      // An event cuts a turning piece short: the shorter piece, with the direction of its own
      // middle (the event may then fall just past it: the next piece takes it).
      if (!turning || event == Event::PieceEnds) break;
      planned = step;
    }
    if (!std::isfinite(step)) return out;   // compression never ends
    work += step * (u[0] + 0.5 * D[0] * step);
    p += step * Eigen::Vector3d(1, g.x(), g.y());
    u += step * D;
    switch (event) {
      case Event::PieceEnds:
        break;
      case Event::SlipStops:
        slipping = false;
        break;
      case Event::CompressionEnds:
        u[0] = 0;
        restitution = true;
        out.p_c = p[0];
        out.work_c = work;
        p_end = (1 + e) * p[0];
        work_end = (1 - e * e) * work;
        break;
      case Event::ImpactEnds:
        out.p = p;
        out.work_f = work;
        out.pieces = piece;
        out.ended = true;
        return out;
    }
  }
  return out;
}

}  // namespace tumble
