// Mass properties of the smooth shapes (geometry/rounded_mass.cpp, revolved_mass.cpp) against a
// stack of thin discs along the axis: a disc of radius rho(z) and mass dm has dm rho^2 / 2 about
// the axis and dm (rho^2 / 4 + z^2) across, about the point z = 0. Simpson's rule on each smooth
// part: the integrands are polynomials of degree 4 in z, so 2000 intervals leave about 1e-13.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

#include "geometry/mass_properties.h"
#include "geometry/primitives.h"

using namespace tumble;

namespace {

struct DiscStack {
  double mass = 0, axial = 0, across = 0;   // across: about z = 0
  // Adds the solid of radius rho(z) for z in [z0, z1], density `rho_kg`.
  void add(double z0, double z1, double rho_kg, const std::function<double(double)>& radius) {
    const int n = 2000;
    const double h = (z1 - z0) / n;
    for (int i = 0; i <= n; ++i) {
      const double z = z0 + i * h, w = (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2)) * h / 3;
      const double r2 = radius(z) * radius(z), dm = rho_kg * M_PI * r2 * w;
      mass += dm, axial += dm * r2 / 2, across += dm * (r2 / 4 + z * z);
    }
  }
};

void checkAgainst(const MassProperties& mp, const DiscStack& s, double centre_z) {
  // the stack's moment across is about z = 0; shifted to the centre of mass
  const double across = s.across - s.mass * centre_z * centre_z;
  CHECK(mp.mass == Approx(s.mass).epsilon(1e-12));
  CHECK(mp.center.z() == Approx(centre_z).margin(1e-12));
  CHECK(mp.inertia(2, 2) == Approx(s.axial).epsilon(1e-12));
  CHECK(mp.inertia(0, 0) == Approx(across).epsilon(1e-12));
  CHECK(mp.inertia(1, 1) == Approx(across).epsilon(1e-12));
  CHECK(std::abs(mp.inertia(0, 1)) < 1e-15);
}

}  // namespace

TEST_CASE("smooth shapes' mass properties are the closed forms", "[geometry][mass]") {
  const double rho = 1000, r = 0.2, L = 0.6;
  SECTION("sphere") {
    DiscStack s;
    s.add(-r, r, rho, [&](double z) { return std::sqrt(std::max(0.0, r * r - z * z)); });
    checkAgainst(massProperties(makeSphere(r), rho), s, 0);
  }
  SECTION("capsule: a cylinder with a hemisphere on each end") {
    DiscStack s;
    auto radius = [&](double z) {
      const double end = std::max(0.0, std::abs(z) - L / 2);
      return std::sqrt(std::max(0.0, r * r - end * end));
    };
    s.add(-L / 2 - r, -L / 2, rho, radius), s.add(-L / 2, L / 2, rho, radius), s.add(L / 2, L / 2 + r, rho, radius);
    checkAgainst(massProperties(makeCapsule(r, L), rho), s, 0);
  }
  SECTION("cylinder") {
    DiscStack s;
    s.add(-L / 2, L / 2, rho, [&](double) { return r; });
    checkAgainst(massProperties(makeCylinder(r, L), rho), s, 0);
  }
  SECTION("tube: the cylinder less its bore") {
    DiscStack outer, bore;
    outer.add(-L / 2, L / 2, rho, [&](double) { return r; });
    bore.add(-L / 2, L / 2, rho, [&](double) { return 0.75 * r; });
    DiscStack s;
    s.mass = outer.mass - bore.mass, s.axial = outer.axial - bore.axial, s.across = outer.across - bore.across;
    checkAgainst(massProperties(makeTube(r, 0.75 * r, L), rho), s, 0);
  }
  SECTION("cone: base at -L/2, apex at +L/2, centre of mass a quarter of the height up") {
    DiscStack s;
    s.add(-L / 2, L / 2, rho, [&](double z) { return r * (L / 2 - z) / L; });
    checkAgainst(massProperties(makeCone(r, L), rho), s, -L / 4);
  }
  CHECK(volume(makeCapsule(r, 0)) == Approx(volume(makeSphere(r))).epsilon(1e-15));
  CHECK(volume(makeCone(r, L)) == Approx(volume(makeCylinder(r, L)) / 3).epsilon(1e-15));
}
