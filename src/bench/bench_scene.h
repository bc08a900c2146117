// The benchmark scenes of docs/bench/scenes.md as plain, engine-neutral data: every body is a
// box, the ground is the half-space z <= 0, one friction and one restitution hold for every pair.
// Each engine driver turns a BenchScene into its own world; the metrics read back box poses only,
// so every engine is measured by the same code.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace tumble::bench {

struct BoxBody {
  Eigen::Vector3d half_extents{0.5, 0.5, 0.5};                     // m
  double mass = 1;                                                 // kg (ignored for walls)
  Eigen::Vector3d x = Eigen::Vector3d::Zero();                     // m, centre
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();           // box axes -> world
  Eigen::Vector3d v = Eigen::Vector3d::Zero();                     // m/s, world
  Eigen::Vector3d w = Eigen::Vector3d::Zero();                     // rad/s, world
};

// Which metric set applies (docs/bench/scenes.md section).
enum class SceneKind { CubeDrop, InclineSlide, InclineStick, Rest, Stack, FreeSpin, Pile, MassRatio,
                       Tunnel };

struct BenchScene {
  std::string id;                       // "S1", "S2a", "S6_300", "S8ccd": names CSV rows and plots
  std::string title;                    // "cube drop"
  SceneKind kind = SceneKind::CubeDrop;
  Eigen::Vector3d gravity{0, 0, -9.81}; // m/s^2
  bool ground = true;                   // the static half-space z <= 0
  std::vector<BoxBody> bodies;          // moving boxes, in this order in every engine
  std::vector<BoxBody> walls;           // static boxes
  double friction = 0.5, restitution = 0;
  double duration = 2;                  // s simulated (before any cut)
  bool ccd = false;                     // engines with continuous collision detection enable it
  std::vector<double> dts;              // s: the steps this scene is swept over
  double bin_half_m = 5;                // S6: the bin's interior is [-bin_half_m, bin_half_m]^2
};

// Scene ids accepted on the command line, in report order: S1 S2a S2b S3 S4 S5 S6_100 S6_300
// S6_1000 S6_10000 S7 S8 S8ccd.
std::vector<std::string> allSceneIds();
// Throws std::invalid_argument for an unknown id. `dts` is used unless the scene fixes its own
// (the piles run at 1/240 s only, as docs/bench/scenes.md says).
BenchScene makeScene(const std::string& id, const std::vector<double>& dts);
// S6: N cubes of 0.5 m dropped in layers into the walled bin (docs/bench/scenes.md gives every
// coordinate and the random orientations: std::mt19937(12345), four N(0,1) draws per cube, w x y z).
// Up to 1000 cubes the bin is 10 m wide and the layers at most 10 x 10; beyond, the 1000-cube pile
// is scaled out: 10 layers of k x k, k = ceil(sqrt(N / 10)), in a bin whose interior is k m wide
// (k = 32 for 10 000 cubes: [-16, 16]^2).
BenchScene makePile(int n);

}  // namespace tumble::bench
