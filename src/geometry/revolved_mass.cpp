// Mass properties of solids of revolution in closed form: a cylinder (a tube: the outer cylinder
// less its bore), and a solid cone (its centre of mass a quarter of the height above the base).
#include <cassert>
#include <cmath>

#include "geometry/mass_properties.h"

namespace tumble {
namespace {

struct Axis {
  Eigen::Vector3d base = Eigen::Vector3d::Zero(), unit = Eigen::Vector3d::UnitZ();
  double height = 0;
};

Axis axisOf(const ConvexPiece& piece) {
  assert(piece.revolved() && piece.vertices.size() == 2);
  Axis a;
  a.base = piece.vertices[0];
  const Eigen::Vector3d d = piece.vertices[1] - piece.vertices[0];
  a.height = d.norm();
  if (a.height > 0) a.unit = d / a.height;
  return a;
}

bool isCone(const ConvexPiece& piece) { return piece.revolution == ConvexPiece::Revolution::Cone; }

}  // namespace

double revolvedVolume(const ConvexPiece& piece) {
  const double r = piece.disc_radius_m, h = axisOf(piece).height;
  if (isCone(piece)) return M_PI * r * r * h / 3;
  return M_PI * (r * r - piece.bore_radius_m * piece.bore_radius_m) * h;
}

MassProperties revolvedMassProperties(const ConvexPiece& piece, double density) {
  const Axis a = axisOf(piece);
  const double r = piece.disc_radius_m, h = a.height;
  MassProperties mp;
  mp.mass = density * revolvedVolume(piece);
  double axial = 0, across = 0;
  if (isCone(piece)) {
    mp.center = a.base + 0.25 * h * a.unit;
    axial = 0.3 * mp.mass * r * r;
    across = mp.mass * (3 * r * r / 20 + 3 * h * h / 80);
  } else {
    // the outer cylinder less the bore: r^2 becomes r^2 + b^2 in both moments
    const double b = piece.bore_radius_m, r2 = r * r + b * b;
    mp.center = a.base + 0.5 * h * a.unit;
    axial = 0.5 * mp.mass * r2;
    across = mp.mass * (3 * r2 + h * h) / 12;
  }
  const Eigen::Matrix3d along = a.unit * a.unit.transpose();
  mp.inertia = across * (Eigen::Matrix3d::Identity() - along) + axial * along;
  return mp;
}

}  // namespace tumble
