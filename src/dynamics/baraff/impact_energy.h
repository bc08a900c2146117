// The rule every restitution law keeps: an impact never adds kinetic energy. Newton's law with
// friction can add some (Kane's paradox: the tangential impulse changes the normal velocity the
// restitution acts on), and so can Poisson's where the slip stops or turns during the impact
// (Stronge, "Rigid body collisions with friction", Proc. R. Soc. Lond. A, 1990). The inelastic
// impact cannot, so the restitution is scaled down as far as the energy needs.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "dynamics/contact.h"
#include "dynamics/world.h"

namespace tumble {

// Relative slack on "no energy added": rounding in summing the energies of a few bodies.
inline constexpr double kEnergySlack = 1e-12;

// The momenta of the bodies an impact touches, to measure its energy and to undo it. In a world
// with joints an impulse moves every body joined to the struck ones too (JointsHoldImpulses,
// contact_jacobian.h), so there it holds every moving body: undoing a trial impulse on the struck
// pair alone left its joints' reaction on the rest of a chain (0.6 J gained in one impact).
struct ImpactMomenta {
  std::vector<int> bodies;
  std::vector<Eigen::Vector3d> P, L;

  ImpactMomenta(const World& world, const std::vector<const Contact*>& points);
  double energy(const World& world) const;
  void restore(World& world) const;
};

// Applies `apply(scale)` (an impact whose restitution is scaled by `scale`); if that adds kinetic
// energy, the largest scale in [0, scale] that adds none (bisection to 1e-6 of it), and if even
// that adds some (an inexact friction solve), `inelastic()`, which must not.
void applyAddingNoEnergy(World& world, const std::vector<const Contact*>& points, double scale,
                         const std::function<void(double)>& apply, const std::function<void()>& inelastic);

}  // namespace tumble
