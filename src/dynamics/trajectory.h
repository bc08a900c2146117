// The motion a simulation produced: the pose and velocity of every body at every frame. The
// renderer and the exporters read it; nothing steps the simulation from here.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace tumble {

struct BodySample {
  Eigen::Vector3d x;          // m, centre of mass, world
  Eigen::Quaterniond q;       // body (principal) frame -> world
  Eigen::Vector3d v;          // m/s, centre of mass, world
  Eigen::Vector3d w;          // rad/s, world
};

struct Trajectory {
  std::vector<std::string> body_names;
  std::vector<double> times;                    // s, one per frame
  std::vector<std::vector<BodySample>> frames;  // frames[k][body]
};

}  // namespace tumble
