#include "bench/bench_scene.h"

#include <cmath>
#include <random>
#include <stdexcept>

namespace tumble::bench {
namespace {

using Eigen::Vector3d;

BoxBody unitCube(const Vector3d& centre, double mass = 1) {
  BoxBody b;
  b.x = centre;
  b.mass = mass;
  return b;
}

BenchScene base(const std::string& id, const std::string& title, SceneKind kind, double duration,
                const std::vector<double>& dts) {
  BenchScene s;
  s.id = id;
  s.title = title;
  s.kind = kind;
  s.duration = duration;
  s.dts = dts;
  return s;
}

BenchScene incline(const std::string& id, SceneKind kind, double mu, const std::vector<double>& dts) {
  BenchScene s = base(id, kind == SceneKind::InclineSlide ? "incline, sliding" : "incline, sticking",
                      kind, 2, dts);
  // The plane stays at z = 0 and gravity is tilted by 30 degrees about +y: down-slope is -x.
  const double theta = M_PI / 6;
  s.gravity = 9.81 * Vector3d(-std::sin(theta), 0, -std::cos(theta));
  s.friction = mu;
  s.bodies.push_back(unitCube({0, 0, 0.5}));
  return s;
}

BenchScene tunnel(const std::string& id, bool ccd, const std::vector<double>& dts) {
  BenchScene s = base(id, ccd ? "tunnelling, CCD on" : "tunnelling", SceneKind::Tunnel, 0.2, dts);
  s.gravity.setZero();
  s.ground = false;
  s.friction = 0;
  s.ccd = ccd;
  BoxBody wall;
  wall.half_extents = {0.005, 2, 1};
  wall.x = {5.005, 0, 0};
  s.walls.push_back(wall);
  for (int j = 0; j < 10; ++j) {
    BoxBody c;
    c.half_extents = Vector3d::Constant(0.05);
    c.x = {-0.173 * j, 0.3 * j - 1.35, 0};
    c.v = {100, 0, 0};
    s.bodies.push_back(c);
  }
  return s;
}

}  // namespace

std::vector<std::string> allSceneIds() {
  return {"S1", "S2a", "S2b", "S3", "S4", "S5", "S6_100", "S6_300", "S6_1000", "S6_10000", "S7", "S8", "S8ccd"};
}

BenchScene makePile(int n) {
  BenchScene s = base("S6_" + std::to_string(n), "pile of " + std::to_string(n) + " boxes",
                      SceneKind::Pile, 5, {1.0 / 240});
  // Up to 1000 cubes: layers of at most 10 x 10 in a bin of interior [-5, 5]^2. Beyond, the
  // 1000-cube pile scaled out: 10 layers of k x k in a bin widened with the layers, so a larger
  // pile has the same height, the same spacing and the same share of cubes near a wall.
  const int k = n <= 1000 ? std::min(10, static_cast<int>(std::ceil(std::sqrt(n / 4.0))))
                          : static_cast<int>(std::ceil(std::sqrt(n / 10.0)));
  s.bin_half_m = n <= 1000 ? 5.0 : 0.5 * k;
  // Bin: four walls 0.5 m thick and 3 m high around the interior.
  const double h = s.bin_half_m;
  const Vector3d wall_x(0.25, h + 0.5, 1.5), wall_y(h + 0.5, 0.25, 1.5);
  for (double side : {-1.0, 1.0}) {
    BoxBody a, b;
    a.half_extents = wall_x;
    a.x = {side * (h + 0.25), 0, 1.5};
    b.half_extents = wall_y;
    b.x = {0, side * (h + 0.25), 1.5};
    s.walls.push_back(a);
    s.walls.push_back(b);
  }
  std::mt19937 rng(12345);
  std::normal_distribution<double> normal;
  for (int i = 0; i < n; ++i) {
    const int layer = i / (k * k), r = i % (k * k);
    BoxBody c;
    c.half_extents = Vector3d::Constant(0.25);
    c.x = {0.95 * (r % k - (k - 1) / 2.0), 0.95 * (r / k - (k - 1) / 2.0), 0.6 + 0.9 * layer};
    // Draws are consumed in w, x, y, z order (the order of evaluation is fixed by sequencing).
    const double w = normal(rng), x = normal(rng), y = normal(rng), z = normal(rng);
    c.q = Eigen::Quaterniond(w, x, y, z).normalized();
    s.bodies.push_back(c);
  }
  return s;
}

BenchScene makeScene(const std::string& id, const std::vector<double>& dts) {
  if (id == "S1") {
    BenchScene s = base(id, "cube drop", SceneKind::CubeDrop, 2, dts);
    s.friction = 0;
    s.restitution = 0.5;
    s.bodies.push_back(unitCube({0, 0, 1.5}));
    return s;
  }
  if (id == "S2a") return incline(id, SceneKind::InclineSlide, 0.3, dts);
  if (id == "S2b") return incline(id, SceneKind::InclineStick, 0.7, dts);
  if (id == "S3") {
    BenchScene s = base(id, "resting cube", SceneKind::Rest, 10, dts);
    s.bodies.push_back(unitCube({0, 0, 0.5}));
    return s;
  }
  if (id == "S4") {
    BenchScene s = base(id, "stack of 10", SceneKind::Stack, 10, dts);
    for (int i = 0; i < 10; ++i) s.bodies.push_back(unitCube({0, 0, 0.5 + i}));
    return s;
  }
  if (id == "S5") {
    BenchScene s = base(id, "free spin", SceneKind::FreeSpin, 10, dts);
    s.gravity.setZero();
    s.ground = false;
    BoxBody b;
    b.half_extents = {0.5, 0.2, 0.05};
    b.x = {0, 0, 1};
    b.w = {0.01, 5.0, 0};
    s.bodies.push_back(b);
    return s;
  }
  if (id.rfind("S6_", 0) == 0) return makePile(std::stoi(id.substr(3)));
  if (id == "S7") {
    BenchScene s = base(id, "mass ratio 1000:1", SceneKind::MassRatio, 5, dts);
    s.bodies.push_back(unitCube({0, 0, 0.5}));
    s.bodies.push_back(unitCube({0, 0, 1.5}, 1000));
    return s;
  }
  if (id == "S8") return tunnel(id, false, dts);
  if (id == "S8ccd") return tunnel(id, true, dts);
  throw std::invalid_argument("unknown scene \"" + id + "\"");
}

}  // namespace tumble::bench
