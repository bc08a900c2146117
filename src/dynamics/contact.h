// One contact point between two bodies, as the dynamics stages see it, and the settings that
// decide when bodies touch, collide or rest.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>

namespace tumble {

struct Contact {
  int a = -1, b = -1;                                   // body indices; b may be static (the ground)
  Eigen::Vector3d point = Eigen::Vector3d::Zero();      // m, world, midway between the surfaces
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();    // unit, world, from A to B
  double depth = 0;                                     // m: > 0 penetrating, < 0 separated
  double restitution = 0, friction = 0;                 // of the pair (see combineMaterials)
};

struct ContactSettings {
  double margin_m = 1e-3;           // m: pairs closer than this are reported by the narrow phase,
                                    // so contacts exist before they touch (cheap, coherent)
  double tolerance_m = 1e-6;        // m: |depth| within this is "touching"; a step that ends deeper
                                    // is bisected back to the first contact (seed 000)
  double resting_speed_m_s = 1e-3;  // m/s: a touching contact approaching slower than this rests;
                                    // faster it collides and gets Newton's impulse
  double sliding_speed_m_s = 1e-5;  // m/s: tangential speed above which friction is dynamic
  int max_bisections = 60;          // halvings of the step: 2^-60 of dt is far below rounding
  bool regula_falsi = false;        // bracket by linear interpolation (Illinois) instead of halving
  // Resting islands up to this many LCP rows (3 per contact) are solved exactly by pivoting
  // (cost ~ rows^3); larger ones (a pile) by Gauss-Seidel sweeps (cost ~ rows per sweep). 256
  // keeps a stack of 20 boxes (80 contacts, 240 rows) exact.
  int max_direct_rows = 256;
};

// Material of a contact pair. Friction: geometric mean (two equal values give that value; an ice
// body slides on anything). Restitution: the mean, so two equal values give that value.
inline double combineFriction(double a, double b) { return std::sqrt(a * b); }
inline double combineRestitution(double a, double b) { return 0.5 * (a + b); }

}  // namespace tumble
