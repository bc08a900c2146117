// Mass properties of rounded pieces in closed form: a solid sphere, and a capsule as a cylinder of
// the segment's length with a hemisphere on each end.
#include <cassert>
#include <cmath>

#include "geometry/mass_properties.h"

namespace tumble {
namespace {

struct Core {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();   // unit; any for a sphere
  double length = 0;                                 // of the segment, 0 for a sphere
};

Core coreOf(const ConvexPiece& piece) {
  assert(piece.rounded() && (piece.vertices.size() == 1 || piece.vertices.size() == 2));
  Core c;
  c.centre = piece.vertices.front();
  if (piece.vertices.size() == 2) {
    const Eigen::Vector3d d = piece.vertices[1] - piece.vertices[0];
    c.centre = 0.5 * (piece.vertices[0] + piece.vertices[1]);
    c.length = d.norm();
    if (c.length > 0) c.axis = d / c.length;
  }
  return c;
}

}  // namespace

double roundedVolume(const ConvexPiece& piece) {
  const Core c = coreOf(piece);
  const double r = piece.radius_m;
  return M_PI * r * r * (4.0 / 3.0 * r + c.length);
}

MassProperties roundedMassProperties(const ConvexPiece& piece, double density) {
  const Core c = coreOf(piece);
  const double r = piece.radius_m, L = c.length;
  const double m_cyl = density * M_PI * r * r * L;
  const double m_ball = density * 4.0 / 3.0 * M_PI * r * r * r;   // both hemispheres together
  // About the centre: the cylinder's moments, and the hemispheres' (each one's centre of mass 3r/8
  // from its flat face, so at L/2 + 3r/8 from the centre; 83/320 m r^2 about it, across).
  const double axial = 0.5 * m_cyl * r * r + 0.4 * m_ball * r * r;
  const double across = m_cyl * (3 * r * r + L * L) / 12 + m_ball * (0.4 * r * r + L * L / 4 + 3 * L * r / 8);
  MassProperties mp;
  mp.mass = m_cyl + m_ball;
  mp.center = c.centre;
  const Eigen::Matrix3d along = c.axis * c.axis.transpose();
  mp.inertia = across * (Eigen::Matrix3d::Identity() - along) + axial * along;
  return mp;
}

}  // namespace tumble
