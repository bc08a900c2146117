// The penalty model's force and friction laws on their own (dynamics/penalty/force_laws.h,
// friction_laws.h, contact_stiffness.h): the closed forms they are built on, and the continuity
// the regularised friction laws promise.
#include <catch2/catch.hpp>

#include <cmath>

#include "dynamics/penalty/contact_stiffness.h"
#include "dynamics/penalty/force_laws.h"
#include "dynamics/penalty/friction_laws.h"

using namespace tumble;

TEST_CASE("kelvin-voigt: the damping ratio found for an e gives that e back, below and above critical damping",
          "[penalty]") {
  CHECK(kelvinVoigtRestitution(0) == 1);
  // At critical damping δ = t exp(-t) (unit ω and closing speed) and the force ends at its
  // inflection t = 2, where δ' = -exp(-2): e = exp(-2), the limit of both closed forms.
  CHECK(std::abs(kelvinVoigtRestitution(1 - 1e-7) - std::exp(-2.0)) <= 1e-6);
  CHECK(std::abs(kelvinVoigtRestitution(1 + 1e-7) - std::exp(-2.0)) <= 1e-6);
  double last = 1;
  for (double zeta = 0.01; zeta < 100; zeta *= 1.3) {
    const double e = kelvinVoigtRestitution(zeta);
    CHECK(e < last);   // monotonic: the inversion by bisection is well posed
    last = e;
  }
  for (double e : {0.05, 0.2, 0.5, 0.8, 0.99}) CHECK(std::abs(kelvinVoigtRestitution(kelvinVoigtDampingRatio(e)) - e) <= 1e-12);
}

TEST_CASE("hertz-type laws: the damping factors are the review's and vanish for an elastic contact", "[penalty]") {
  CHECK(hertzDampingFactor(NormalForceLaw::HuntCrossley, 0.6) == Approx(1.5 * 0.4));
  CHECK(hertzDampingFactor(NormalForceLaw::LankaraniNikravesh, 0.6) == Approx(0.75 * (1 - 0.36)));
  CHECK(hertzDampingFactor(NormalForceLaw::Flores, 0.6) == Approx(8 * 0.4 / 3.0));
  for (NormalForceLaw law : {NormalForceLaw::HuntCrossley, NormalForceLaw::LankaraniNikravesh, NormalForceLaw::Flores})
    CHECK(hertzDampingFactor(law, 1) == 0);
  NormalLawState s{1e6, 1.5, 0, 0.6, 2.0};
  CHECK(normalForce(s, -1e-3, 1) == 0);                           // apart: no force
  CHECK(normalForce(s, 1e-4, 0) == Approx(1e6 * std::pow(1e-4, 1.5)));
  CHECK(normalForce(s, 1e-4, -10) == 0);                          // never a pull
  CHECK(storedEnergy(s, 1e-4) == Approx(1e6 * std::pow(1e-4, 2.5) / 2.5));
}

TEST_CASE("friction laws: zero at rest, continuous at their ramp speed, coulomb's mu f_n beyond it", "[penalty]") {
  PenaltySettings p;
  for (FrictionLaw law : {FrictionLaw::Coulomb, FrictionLaw::Threlfall, FrictionLaw::BengisuAkay, FrictionLaw::Ambrosio}) {
    p.friction_law = law;
    const FrictionLawState s = frictionLawOf(p, 0.5);
    CHECK(frictionForce(s, 0, 10) == 0);
    const double below = frictionForce(s, s.v1 * (1 - 1e-9), 10), above = frictionForce(s, s.v1 * (1 + 1e-9), 10);
    // Threlfall's law jumps by 1 - exp(-3) - 0.95 = 2.1e-4 of mu f_n at v1 as the review prints it.
    CHECK(std::abs(below - above) <= (law == FrictionLaw::Threlfall ? 2.2e-4 * 5 : 1e-6));
  }
  p.friction_law = FrictionLaw::Coulomb;
  CHECK(frictionForce(frictionLawOf(p, 0.5), 1.0, 10) == Approx(5));
  p.friction_law = FrictionLaw::BengisuAkay;
  const FrictionLawState ba = frictionLawOf(p, 0.5);
  CHECK(frictionForce(ba, ba.v1, 10) == Approx(0.6 * 10));            // the static peak
  CHECK(frictionForce(ba, 100, 10) == Approx(0.5 * 10).epsilon(1e-9)); // down to mu_d
  p.friction_law = FrictionLaw::Ambrosio;
  const FrictionLawState am = frictionLawOf(p, 0.5);
  CHECK(frictionForce(am, am.v0 * 0.5, 10) == 0);                     // below its dead speed
}

TEST_CASE("stiffness from materials: Hertz's K = 4/3 E* sqrt(R*), a flat punch's k = 2 E* R*", "[penalty]") {
  RigidBody steel, rubber;
  steel.youngs_modulus_pa = 2e11;
  steel.poisson_ratio = 0.3;
  rubber.youngs_modulus_pa = 1e7;
  rubber.poisson_ratio = 0.49;
  const double e_star = 1 / ((1 - 0.09) / 2e11 + (1 - 0.49 * 0.49) / 1e7);
  CHECK(effectiveModulus(steel, rubber) == Approx(e_star));
  CHECK(effectiveRadius(0.1, INFINITY) == Approx(0.1));
  CHECK(effectiveRadius(0.1, 0.1) == Approx(0.05));
  CHECK(materialStiffness(NormalForceLaw::Hertz, e_star, 0.05) == Approx(4.0 / 3.0 * e_star * std::sqrt(0.05)));
  CHECK(materialStiffness(NormalForceLaw::Hooke, e_star, 0.05) == Approx(2 * e_star * 0.05));
}
