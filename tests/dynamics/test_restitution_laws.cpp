// Restitution laws (baraff/restitution_laws.h) against an analysis of the planar impact written
// here: a slender rod (a capsule 1 m long, 1 kg) whose lower end strikes a rough floor at 45
// degrees while moving sideways, so that friction stops the slip during the impact and then holds
// it or reverses it. In the rod's plane the lower end's velocity is linear in the impulse there,
// and with the normal impulse p_n as the clock every phase (slip, stick, reversed slip) is a
// straight line: the analysis below follows them exactly, phase by phase (Routh's method; Stronge,
// "Impact Mechanics", 2000). The simulator must agree to 1e-9 of the speed: both sides solve the
// same piecewise-linear problem exactly, so only rounding separates them (1e-15 measured; the
// margin covers the contact point, which the narrow phase places to within 1e-12 m).
#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <sstream>

#include "dynamics/baraff/collisions.h"
#include "dynamics/baraff/point_impact.h"
#include "dynamics/contact_detection.h"
#include "dynamics/pipeline.h"
#include "scene/scene_loader.h"
#include "scene/world_builder.h"

using namespace tumble;

namespace {

constexpr double kLength = 1, kRadius = 0.01, kTilt = M_PI / 4;
constexpr double kTolerance = 1e-9;

const char* lawName(RestitutionLaw law) {
  return law == RestitutionLaw::Newton ? "newton" : law == RestitutionLaw::Poisson ? "poisson" : "stronge";
}

// The rod's lower end in its plane (h horizontal, z up) from the centre of mass, its mass and its
// moment of inertia about the plane's normal. An impulse (p_t, p_n) at the end changes the end's
// velocity (u_t, u_n) by
//   du_t = a_tt dp_t + a_tn dp_n,   du_n = a_tn dp_t + a_nn dp_n,
//   a_tt = 1/m + r_z^2/I,  a_nn = 1/m + r_x^2/I,  a_tn = -r_x r_z / I
// (dv = p/m, dw = (r_z p_t - r_x p_n)/I, u = v + w x r).
struct PlanarRod {
  double m = 0, I = 0, rx = 0, rz = 0;
  double att() const { return 1 / m + rz * rz / I; }
  double ann() const { return 1 / m + rx * rx / I; }
  double atn() const { return -rx * rz / I; }
};

struct PlanarImpulse {
  double pt = 0, pn = 0;
  int slip_stops = 0;
  bool sticks = false, reverses = false;
};

double sign(double x) { return x > 0 ? 1 : -1; }

// Poisson's or Stronge's law, phase by phase. A phase has a fixed ratio k = dp_t/dp_n: -mu sign(u_t)
// while slipping; once the slip has stopped, -a_tn/a_tt (the impulse that holds it) if that is
// within mu, else -mu sign(a_tn) (it slides on the way a_tn drives it). A phase ends where the slip
// stops, where compression ends (u_n = 0: p_c and the work W_c = integral of u_n dp_n), or where the
// law ends the impact: p_n = (1 + e) p_c, or W = (1 - e^2) W_c.
PlanarImpulse planarLaw(const PlanarRod& rod, double ut, double un, double mu, double e, RestitutionLaw law) {
  PlanarImpulse out;
  double work = 0, pc = -1, work_c = 0;
  for (int phase = 0; phase < 8; ++phase) {
    double k = 0;
    if (ut != 0) {
      k = -mu * sign(ut);
    } else if (std::abs(rod.atn() / rod.att()) <= mu) {
      k = -rod.atn() / rod.att();
      out.sticks = true;
    } else {
      k = -mu * sign(rod.atn());
      out.reverses = true;
    }
    const double dut = rod.atn() + rod.att() * k, dun = rod.atn() * k + rod.ann();
    double step = INFINITY;
    int event = 0;   // 1: slip stops, 2: compression ends, 3: the impact ends
    if (ut != 0 && ut * dut < 0) step = -ut / dut, event = 1;
    if (pc < 0) {
      if (dun > 0 && -un / dun < step) step = -un / dun, event = 2;
    } else {
      double end = 0;
      if (law == RestitutionLaw::Poisson) {
        end = (1 + e) * pc - out.pn;
      } else {
        const double c = (1 - e * e) * work_c - work;   // W gains c over the phase: un t + dun t^2 / 2 = c
        end = dun == 0 ? c / un : (-un + std::sqrt(un * un + 2 * dun * c)) / dun;
      }
      if (end < step) step = end, event = 3;
    }
    REQUIRE(std::isfinite(step));
    work += step * (un + 0.5 * dun * step);
    out.pn += step;
    out.pt += k * step;
    ut += dut * step;
    un += dun * step;
    if (event == 1) ut = 0, ++out.slip_stops;
    if (event == 2) un = 0, pc = out.pn, work_c = work;
    if (event == 3) return out;
  }
  FAIL("the planar impact did not end in 8 phases");
  return out;
}

// Newton's law: u_n+ = -e u_n-, the slip held if the friction cone allows, else sliding at the cone
// against the final slip.
PlanarImpulse planarNewton(const PlanarRod& rod, double ut, double un, double mu, double e) {
  PlanarImpulse out;
  const double det = rod.att() * rod.ann() - rod.atn() * rod.atn();
  const double dut = -ut, dun = -(1 + e) * un;
  out.pt = (rod.ann() * dut - rod.atn() * dun) / det;
  out.pn = (rod.att() * dun - rod.atn() * dut) / det;
  if (std::abs(out.pt) <= mu * out.pn) return out;
  for (double s : {1.0, -1.0}) {
    out.pn = dun / (rod.ann() - mu * s * rod.atn());
    out.pt = -mu * s * out.pn;
    if (s * (ut + (rod.atn() - mu * s * rod.att()) * out.pn) >= 0) return out;
  }
  FAIL("no sliding direction is consistent");
  return out;
}

// A strike: the rod tilted 45 degrees from the floor in the vertical plane at `yaw` about z, its
// centre moving at (vx along the plane, vz up), turning at `spin` about the plane's normal.
struct Strike {
  double vx = 0, vz = 0, spin = 0, yaw = 0;
  double mu = 0.5, e = 0.5;
};

struct PlaneFrame {
  Eigen::Vector3d h, normal;   // the plane's horizontal axis and its normal (the rod's turning axis)
};

PlaneFrame frameOf(const Strike& s) {
  const Eigen::AngleAxisd yaw(s.yaw, Eigen::Vector3d::UnitZ());
  return {yaw * Eigen::Vector3d::UnitX(), yaw * Eigen::Vector3d::UnitY()};
}

// The rod's axis in the world, towards its upper end (the principal axis of least moment).
Eigen::Vector3d rodAxis(const RigidBody& rod) {
  Eigen::Index along = 0;
  rod.inertia_body.minCoeff(&along);
  const Eigen::Vector3d axis = rod.q * Eigen::Vector3d::Unit(along);
  return axis.z() < 0 ? Eigen::Vector3d(-axis) : axis;
}

// The rod on a floor plane, both of the strike's friction and restitution, simulated with `law`.
BuiltWorld rodWorld(const Strike& s, RestitutionLaw law) {
  std::ostringstream json;
  json.precision(17);
  json << R"({ "schema_version": 1, "simulation": { "restitution_law": ")" << lawName(law) << R"(" },
    "bodies": [ { "name": "floor", "shape": "plane", "friction": )" << s.mu << R"(, "restitution": )" << s.e << R"( },
                { "name": "rod", "shape": "capsule", "radius_m": )" << kRadius << R"(, "length_m": )" << kLength
       << R"(, "mass_kg": 1, "position_m": [0, 0, 2], "friction": )" << s.mu << R"(, "restitution": )" << s.e
       << " } ] }";
  BuiltWorld built = buildWorld(parseScene(json.str(), "rod.json"));
  RigidBody& rod = built.world.bodies[1];
  const PlaneFrame f = frameOf(s);
  // The body frame is the principal one: the rod's axis is the one of least moment.
  Eigen::Index along = 0;
  rod.inertia_body.minCoeff(&along);
  rod.q = Eigen::AngleAxisd(s.yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(kTilt, Eigen::Vector3d::UnitY()) *
          Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::Unit(along), Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d axis = rodAxis(rod);   // towards the upper end
  rod.x = Eigen::Vector3d(0, 0, 0.5 * kLength * axis.z() + kRadius);   // the lower end's ball touches z = 0
  rod.P = rod.mass * (s.vx * f.h + s.vz * Eigen::Vector3d::UnitZ());
  const Eigen::Matrix3d R = rod.rotation();
  rod.L = R * rod.inertia_body.asDiagonal() * R.transpose() * (s.spin * f.normal);
  return built;
}

PlanarRod planarRod(const RigidBody& rod, const Strike& s) {
  const Eigen::Vector3d r = -0.5 * kLength * rodAxis(rod) - kRadius * Eigen::Vector3d::UnitZ();   // the lowest point
  return {rod.mass, rod.inertia_body.maxCoeff(), r.dot(frameOf(s).h), r.z()};
}

// The rod's motion in its plane: (vx, vz, w).
Eigen::Vector3d planarMotion(const RigidBody& rod, const Strike& s) {
  const PlaneFrame f = frameOf(s);
  const Eigen::Vector3d v = rod.velocity();
  return {v.dot(f.h), v.z(), rod.angularVelocity().dot(f.normal)};
}

Eigen::Vector3d afterImpulse(const PlanarRod& rod, const Strike& s, const PlanarImpulse& p) {
  return {s.vx + p.pt / rod.m, s.vz + p.pn / rod.m, s.spin + (rod.rz * p.pt - rod.rx * p.pn) / rod.I};
}

double kineticEnergy(const PlanarRod& rod, const Eigen::Vector3d& m) {
  return 0.5 * rod.m * (m[0] * m[0] + m[1] * m[1]) + 0.5 * rod.I * m[2] * m[2];
}

// The analysis's answer for the strike under `law`.
Eigen::Vector3d analysed(const PlanarRod& rod, const Strike& s, RestitutionLaw law, PlanarImpulse* phases = nullptr) {
  const double ut = s.vx + s.spin * rod.rz, un = s.vz - s.spin * rod.rx;
  const PlanarImpulse p =
      law == RestitutionLaw::Newton ? planarNewton(rod, ut, un, s.mu, s.e) : planarLaw(rod, ut, un, s.mu, s.e, law);
  if (phases) *phases = p;
  return afterImpulse(rod, s, p);
}

// The simulator's answer: the contact detected, and the collision stage run on it.
Eigen::Vector3d collided(const Strike& s, RestitutionLaw law) {
  BuiltWorld built = rodWorld(s, law);
  ContactDetector detector(built.world);
  std::vector<Contact> contacts;
  detector.detect(built.world, built.step.contact, contacts);
  REQUIRE(contacts.size() == 1);
  ContactSolveStats stats;
  REQUIRE(resolveCollisions(built.world, contacts, built.step.contact, minBounceSpeed(built.world, built.step.contact, built.step.dt), built.step.dt, stats));
  const Eigen::Vector3d normal_axis = frameOf(s).normal;
  CHECK(std::abs(built.world.bodies[1].velocity().dot(normal_axis)) <= 1e-12);   // stays in its plane
  return planarMotion(built.world.bodies[1], s);
}

double speedOf(const Strike& s) { return std::hypot(s.vx, s.vz) + 0.5 * kLength * std::abs(s.spin); }

// Differences in (vx, vz, w), the spin taken at the rod's half length: m/s.
double difference(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  Eigen::Vector3d d = a - b;
  d[2] *= 0.5 * kLength;
  return d.lpNorm<Eigen::Infinity>();
}

const Strike kHaltsThenReverses{1.0, -2.0, 0, 0, 0.5, 0.5};   // stops in compression; sticking needs mu 0.6
const Strike kReversesInRestitution{2.5, -2.0, 0, 0, 0.5, 0.8};
const Strike kHaltsThenSticks{1.0, -2.0, 0, 0, 0.7, 0.5};

}  // namespace

TEST_CASE("restitution laws: a rod striking a rough floor at 45 degrees matches the planar impulse analysis for each law", "[restitution]") {
  struct Case {
    const char* name;
    Strike strike;
    bool sticks, reverses;
  };
  for (const Case& c : {Case{"slip halts in compression then reverses", kHaltsThenReverses, false, true},
                        Case{"slip reverses in restitution", kReversesInRestitution, false, true},
                        Case{"slip halts then sticks", kHaltsThenSticks, true, false}}) {
    const RigidBody rod_body = rodWorld(c.strike, RestitutionLaw::Newton).world.bodies[1];
    const PlanarRod rod = planarRod(rod_body, c.strike);
    const double before = kineticEnergy(rod, {c.strike.vx, c.strike.vz, c.strike.spin});
    Eigen::Vector3d answers[3];
    for (RestitutionLaw law : {RestitutionLaw::Newton, RestitutionLaw::Poisson, RestitutionLaw::Stronge}) {
      INFO(c.name << ", " << lawName(law));
      PlanarImpulse phases;
      const Eigen::Vector3d expected = analysed(rod, c.strike, law, &phases);
      answers[static_cast<int>(law)] = expected;
      if (law != RestitutionLaw::Newton) {
        // The strike does what it is named for.
        CHECK(phases.slip_stops == 1);
        CHECK(phases.sticks == c.sticks);
        CHECK(phases.reverses == c.reverses);
      }
      // Where the law itself would add energy the simulator scales its restitution down
      // (impact_energy.h), which the analysis does not: the strikes are chosen where none does.
      REQUIRE(kineticEnergy(rod, expected) <= before);
      const Eigen::Vector3d got = collided(c.strike, law);
      INFO("expected " << expected.transpose() << ", got " << got.transpose());
      CHECK(difference(got, expected) <= kTolerance * speedOf(c.strike));
    }
    // The laws differ here (by far more than the tolerance).
    CHECK(difference(answers[0], answers[1]) > 1e-3);
    CHECK(difference(answers[0], answers[2]) > 1e-3);
    CHECK(difference(answers[1], answers[2]) > 1e-3);
  }
}

TEST_CASE("restitution laws: the rod's strike in a vertical plane at any yaw gives the planar answer in 3-D", "[restitution]") {
  // The slip is now along both tangents of the contact frame (world x and y): the 3-D path must
  // see that it keeps its direction and take each phase whole.
  for (double yaw : {0.3, 2.0, -2.7}) {
    Strike s = kReversesInRestitution;
    s.yaw = yaw;
    s.spin = 0.7;
    const PlanarRod rod = planarRod(rodWorld(s, RestitutionLaw::Newton).world.bodies[1], s);
    for (RestitutionLaw law : {RestitutionLaw::Poisson, RestitutionLaw::Stronge}) {
      INFO("yaw " << yaw << ", " << lawName(law));
      CHECK(difference(collided(s, law), analysed(rod, s, law)) <= kTolerance * speedOf(s));
    }
  }
}

TEST_CASE("restitution laws: one step of the pipeline applies the law's impulse at the strike", "[restitution]") {
  // The rod touches the floor as the step starts: the collision stage takes the impact at t = 0,
  // then the rod flies free for the step (gravity adds g dt to the velocity; the spin is free).
  for (RestitutionLaw law : {RestitutionLaw::Poisson, RestitutionLaw::Stronge}) {
    INFO(lawName(law));
    const Strike& s = kHaltsThenReverses;
    BuiltWorld built = rodWorld(s, law);
    const PlanarRod rod = planarRod(built.world.bodies[1], s);
    Pipeline pipeline(built.world, built.step);
    pipeline.step(built.world, built.step);
    Eigen::Vector3d got = planarMotion(built.world.bodies[1], s);
    got[1] -= built.world.gravity.z() * built.step.dt;
    CHECK(difference(got, analysed(rod, s, law)) <= kTolerance * speedOf(s));
  }
}

TEST_CASE("restitution laws: without friction all three give Newton's answer", "[restitution]") {
  SECTION("one point: the rod") {
    Strike s = kHaltsThenReverses;
    s.mu = 0;
    s.spin = -1.5;
    const Eigen::Vector3d newton = collided(s, RestitutionLaw::Newton);
    const PlanarRod rod = planarRod(rodWorld(s, RestitutionLaw::Newton).world.bodies[1], s);
    CHECK(difference(newton, analysed(rod, s, RestitutionLaw::Newton)) <= kTolerance * speedOf(s));
    for (RestitutionLaw law : {RestitutionLaw::Poisson, RestitutionLaw::Stronge}) {
      INFO(lawName(law));
      CHECK(difference(collided(s, law), newton) <= kTolerance * speedOf(s));
    }
  }
  SECTION("four points: a tilted cube landing on a face, spinning") {
    // Four corners at once, with the cube turning about a horizontal axis so the corners approach
    // at different speeds: the two-phase LCPs (two_phase_impact.h) against Newton's one LCP.
    auto land = [](RestitutionLaw law) {
      std::string json = std::string(R"({ "schema_version": 1, "simulation": { "restitution_law": ")") + lawName(law) +
                         R"(" }, "bodies": [ { "shape": "plane", "friction": 0, "restitution": 0.6 },
                            { "shape": "box", "size_m": [1, 0.6, 0.3], "mass_kg": 2, "position_m": [0, 0, 0.15],
                              "friction": 0, "restitution": 0.6 } ] })";
      BuiltWorld built = buildWorld(parseScene(json, "cube.json"));
      RigidBody& cube = built.world.bodies[1];
      cube.P = cube.mass * Eigen::Vector3d(0.4, 0, -1.5);
      cube.L = cube.inertia_body.cwiseProduct(Eigen::Vector3d(0.5, 0.3, 0.2));   // body axes = world axes
      ContactDetector detector(built.world);
      std::vector<Contact> contacts;
      detector.detect(built.world, built.step.contact, contacts);
      REQUIRE(contacts.size() == 4);
      ContactSolveStats stats;
      resolveCollisions(built.world, contacts, built.step.contact, minBounceSpeed(built.world, built.step.contact, built.step.dt), built.step.dt, stats);
      return std::make_pair(cube.velocity(), cube.angularVelocity());
    };
    const auto newton = land(RestitutionLaw::Newton);
    CHECK(newton.first.z() > 0);
    for (RestitutionLaw law : {RestitutionLaw::Poisson, RestitutionLaw::Stronge}) {
      INFO(lawName(law));
      const auto got = land(law);
      CHECK((got.first - newton.first).norm() <= 1e-9 * 1.5);
      CHECK((got.second - newton.second).norm() * 0.5 <= 1e-9 * 1.5);
    }
  }
}

TEST_CASE("restitution laws: random 3-D point impacts end as each law says and Stronge's never adds energy", "[restitution]") {
  // Random effective masses, velocities, mu and e, the slip turning in 3-D. In the contact frame
  // the kinetic energy changes by u.p + p.K.p / 2 for an impulse p.
  std::mt19937 rng(20261124);
  auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  int ended = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    Eigen::Matrix3d B;
    for (int i = 0; i < 9; ++i) B(i / 3, i % 3) = uniform(-1, 1);
    const Eigen::Matrix3d K = B * B.transpose() + 0.05 * Eigen::Matrix3d::Identity();
    const Eigen::Vector3d u(uniform(-3, -0.1), uniform(-3, 3), uniform(-3, 3));
    const double mu = uniform(0, 1.5), e = uniform(0, 1);
    for (RestitutionLaw law : {RestitutionLaw::Poisson, RestitutionLaw::Stronge}) {
      INFO("trial " << trial << ", " << lawName(law));
      const PointImpact impact = followPointImpact(K, u, mu, e, law);
      if (!impact.ended) continue;   // compression never ends: Newton's LCP takes it
      ++ended;
      const Eigen::Vector3d after = u + K * impact.p;
      const double scale = u.norm();
      CHECK(after[0] >= -1e-9 * scale);                                         // nothing approaches
      CHECK(impact.p.tail<2>().norm() <= mu * impact.p[0] * (1 + 1e-9) + 1e-12);   // Coulomb
      const double energy = u.dot(impact.p) + 0.5 * impact.p.dot(K * impact.p);
      const double rest = std::abs(after[0]) <= 1e-9 * scale;   // ended back at rest along the normal
      if (law == RestitutionLaw::Poisson && !rest) CHECK(impact.p[0] == Approx(impact.p_c * (1 + e)).epsilon(1e-9));
      if (law == RestitutionLaw::Stronge) {
        if (!rest) CHECK(impact.work_f == Approx((1 - e * e) * impact.work_c).epsilon(1e-9));
        CHECK(energy <= 1e-9 * std::abs(impact.work_c));
      }
    }
  }
  CHECK(ended > 3000);
}

namespace {

// The impact of one point in 3-D, integrated here as the ODE it is: with the normal impulse as the
// clock, dp_t/dp_n = -mu s/|s| (s the slip, u = u0 + K p), dW/dp_n = u_n, by RK4 in steps of 1e-5
// of the frictionless compression impulse; compression and restitution end where u_n and W cross
// their targets, found by linear interpolation within the step (error ~ step^2). Only for slips
// that never stop (the caller checks `least_slip`).
struct Reference {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  double least_slip = INFINITY, turned = 0;   // rad
};

Reference referenceImpact(const Eigen::Matrix3d& K, const Eigen::Vector3d& u0, double mu, double e, RestitutionLaw law) {
  using State = Eigen::Vector3d;   // p_t (2) and W
  const double h = 1e-5 * -u0[0] / K(0, 0);
  auto velocity = [&](double pn, const State& y) { return Eigen::Vector3d(u0 + K * Eigen::Vector3d(pn, y[0], y[1])); };
  auto rate = [&](double pn, const State& y) {
    const Eigen::Vector3d u = velocity(pn, y);
    const Eigen::Vector2d g = -mu * u.tail<2>().normalized();
    return State(g.x(), g.y(), u[0]);
  };
  Reference out;
  double pn = 0, pc = -1, target = 0;
  State y = State::Zero();
  double angle = std::atan2(u0[2], u0[1]);
  for (long i = 0; i < 100000000; ++i) {
    const State k1 = rate(pn, y), k2 = rate(pn + h / 2, y + h / 2 * k1), k3 = rate(pn + h / 2, y + h / 2 * k2),
                k4 = rate(pn + h, y + h * k3);
    const State next = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    const Eigen::Vector3d u = velocity(pn, y), v = velocity(pn + h, next);
    out.least_slip = std::min(out.least_slip, v.tail<2>().norm());
    const double a = std::atan2(v[2], v[1]);
    out.turned += std::abs(std::remainder(a - angle, 2 * M_PI));
    angle = a;
    if (pc < 0 && v[0] >= 0) {   // compression ends within the step
      pc = pn + h * (-u[0]) / (v[0] - u[0]);
      target = law == RestitutionLaw::Poisson ? (1 + e) * pc
                                              : (1 - e * e) * (y[2] + (next[2] - y[2]) * (pc - pn) / h);
    }
    if (pc >= 0) {
      const double at = law == RestitutionLaw::Poisson ? pn : y[2], after = law == RestitutionLaw::Poisson ? pn + h : next[2];
      if (after >= target && pn + h > pc) {
        const double f = (target - at) / (after - at);
        out.p = Eigen::Vector3d(pn + f * h, y[0] + f * (next[0] - y[0]), y[1] + f * (next[1] - y[1]));
        return out;
      }
    }
    y = next;
    pn += h;
  }
  FAIL("the reference impact did not end");
  return out;
}

}  // namespace

TEST_CASE("restitution laws: a 3-D impact whose slip turns matches a fine integration of the slip equation", "[restitution]") {
  // Random effective masses and velocities, kept where the slip turns by more than 0.3 rad and
  // never comes within a fifth of its start to stopping (the reference does not follow a stop).
  // The pieces turn the slip by 0.003 rad each, taking the direction at their middle: 1e-4 of
  // the impulse allows for that (1e-6 measured).
  std::mt19937 rng(7);
  auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  int checked = 0;
  for (int trial = 0; trial < 200 && checked < 6; ++trial) {
    Eigen::Matrix3d B;
    for (int i = 0; i < 9; ++i) B(i / 3, i % 3) = uniform(-1, 1);
    const Eigen::Matrix3d K = B * B.transpose() + 0.05 * Eigen::Matrix3d::Identity();
    const Eigen::Vector3d u(uniform(-3, -0.1), uniform(-3, 3), uniform(-3, 3));
    const double mu = uniform(0, 0.6), e = uniform(0.2, 1);
    const RestitutionLaw law = trial % 2 ? RestitutionLaw::Poisson : RestitutionLaw::Stronge;
    const PointImpact impact = followPointImpact(K, u, mu, e, law);
    if (!impact.ended) continue;
    const Reference ref = referenceImpact(K, u, mu, e, law);
    if (ref.least_slip < 0.2 * u.tail<2>().norm() || ref.turned < 0.3) continue;
    ++checked;
    INFO("trial " << trial << ", " << lawName(law) << ": turned " << ref.turned << " rad, pieces " << impact.pieces);
    INFO("got " << impact.p.transpose() << ", reference " << ref.p.transpose());
    CHECK((impact.p - ref.p).norm() <= 1e-4 * ref.p.norm());
  }
  CHECK(checked == 6);
}
