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
  // 2.2.2 sizes its buffers from these by hand (results-peers.md: 12 N + 40 contacts, 4 rows each).
  // It also keeps a dense njmax x njmax matrix (efc_AR) in one buffer whose size must fit an int:
  // 4 (12 N + 40) rows no longer fit above ~220 boxes ("could not create mjData"), so the rows are
  // capped at 11000 (0.97 GB for that matrix). A pile that needs more rows drops constraints,
  // which MuJoCo counts as a warning and the report marks INVALID.
  const std::size_t nconmax = 12 * n + 40, njmax = std::min<std::size_t>(4 * nconmax, 11000);
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
