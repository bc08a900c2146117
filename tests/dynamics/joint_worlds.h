// Worlds with joints for the joint tests, built through the scene's own path (BodySpec and
// JointSpec into buildWorld), and a runner that steps them through the Pipeline.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "dynamics/pipeline.h"
#include "scene/world_builder.h"

namespace tumble::joint_test {

// A box rod of length `length` (m) along its z, width `width`, mass `mass`, hanging from the world
// point `anchor` by its top end, turned by `angle` (rad) about the world y axis.
BodySpec rod(const std::string& name, const Eigen::Vector3d& anchor, double angle, double length = 1,
             double width = 0.02, double mass = 1);
// The lower end of such a rod.
Eigen::Vector3d rodEnd(const Eigen::Vector3d& anchor, double angle, double length = 1);

// A chain of `links` rods ("link0", ...) of `length` and `mass`, straight out along +x from `top`,
// where the first hangs from the world; each joined to the next by a ball joint at their ends.
void addChain(int links, const Eigen::Vector3d& top, double length, double mass, std::vector<BodySpec>& bodies,
              std::vector<JointSpec>& joints);

JointSpec joint(JointType type, const std::string& a, const std::string& b, const Eigen::Vector3d& anchor,
                const Eigen::Vector3d& axis = Eigen::Vector3d::UnitY());

struct JointRun {
  BuiltWorld built;
  StepSettings step;
};

// A scene of these bodies and joints under `model`, with gravity, without sleep, RK4 at `dt`.
JointRun makeRun(std::vector<BodySpec> bodies, std::vector<JointSpec> joints, ContactModel model,
                 double dt = 1.0 / 240, const Eigen::Vector3d& gravity = {0, 0, -9.81});

// Steps `run` for `seconds`, calling `after` after every step.
void simulate(JointRun& run, double seconds, const std::function<void(const World&)>& after);

// Total energy: kinetic plus gravitational (zero at z = 0).
double totalEnergy(const World& world);

}  // namespace tumble::joint_test
