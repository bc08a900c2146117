#include "bench/peers/mjcf_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace tumble::bench {
namespace {

std::string vec(const Eigen::Vector3d& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g", v.x(), v.y(), v.z());
  return buf;
}

std::string quat(const Eigen::Quaterniond& q) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g %.17g", q.w(), q.x(), q.y(), q.z());
  return buf;
}

}  // namespace

double dampingRatioFor(double e) {
  if (e <= 0) return 1;
  const double l = std::log(e);
  return -l / std::sqrt(M_PI * M_PI + l * l);
}

std::string mjcfOf(const BenchScene& scene, double dt, const MujocoOptions& opt) {
  const std::size_t n = scene.bodies.size();
  // 2.2.2 sizes its buffers from these by hand (docs/bench/peers.md: 12 N + 40 contacts, 4 rows each).
  // Its mjData is one buffer whose size must fit an int (2.1 GB), and it grows with njmax^2 (dense
  // constraint matrices) and njmax nv (Jacobians): 4 (12 N + 40) rows no longer fit above ~220
  // boxes ("could not create mjData"). Measured here: 11000 rows fit at N = 300 and 11697 do not;
  // 16 r^2 + 16 nv r <= 1.8e9 bytes stays inside both. A pile that needs more rows drops
  // constraints, which MuJoCo counts and the report marks INVALID.
  const double nv = 6.0 * static_cast<double>(n), bytes = 1.8e9;
  const double row_cap = (-16 * nv + std::sqrt(256 * nv * nv + 64 * bytes)) / 32;
  const std::size_t nconmax = 12 * n + 40;
  const std::size_t njmax = std::min<std::size_t>(4 * nconmax, static_cast<std::size_t>(row_cap));
  std::ostringstream x;
  x.precision(17);
  x << "<mujoco model=\"" << scene.id << "\">\n";
  x << "  <option timestep=\"" << dt << "\" gravity=\"" << vec(scene.gravity) << "\""
    << (opt.cg ? " solver=\"CG\"" : "") << "/>\n";
  x << "  <size nconmax=\"" << nconmax << "\" njmax=\"" << njmax << "\"/>\n";
  x << "  <default><geom condim=\"" << (scene.friction > 0 ? 3 : 1) << "\" friction=\"" << scene.friction
    << " 0.005 0.0001\" solref=\"0.02 " << dampingRatioFor(scene.restitution)
    << "\" solimp=\"0.9 0.95 0.001\"/></default>\n";
  x << "  <worldbody>\n";
  if (scene.ground) x << "    <geom type=\"plane\" size=\"0 0 1\"/>\n";
  for (const BoxBody& w : scene.walls)
    x << "    <geom type=\"box\" size=\"" << vec(w.half_extents) << "\" pos=\"" << vec(w.x) << "\" quat=\"" << quat(w.q) << "\"/>\n";
  for (std::size_t i = 0; i < n; ++i) {
    const BoxBody& b = scene.bodies[i];
    x << "    <body name=\"b" << i << "\" pos=\"" << vec(b.x) << "\" quat=\"" << quat(b.q) << "\"><freejoint/>"
      << "<geom type=\"box\" size=\"" << vec(b.half_extents) << "\" mass=\"" << b.mass << "\"/></body>\n";
  }
  x << "  </worldbody>\n</mujoco>\n";
  return x.str();
}

}  // namespace tumble::bench
