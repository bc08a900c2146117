#include "joint_worlds.h"

#include <cmath>

namespace tumble::joint_test {

BodySpec rod(const std::string& name, const Eigen::Vector3d& anchor, double angle, double length, double width,
             double mass) {
  BodySpec b;
  b.name = name;
  b.shape = ShapeKind::Box;
  b.box_size_m = {width, width, length};
  b.mass_kg = mass;
  b.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY()));
  b.position_m = anchor + b.orientation * Eigen::Vector3d(0, 0, -length / 2);
  return b;
}

Eigen::Vector3d rodEnd(const Eigen::Vector3d& anchor, double angle, double length) {
  return anchor + Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY()) * Eigen::Vector3d(0, 0, -length);
}

JointSpec joint(JointType type, const std::string& a, const std::string& b, const Eigen::Vector3d& anchor,
                const Eigen::Vector3d& axis) {
  JointSpec j;
  j.type = type;
  j.body_a = a;
  j.body_b = b;
  j.anchor_m = anchor;
  j.axis = axis.normalized();
  return j;
}

void addChain(int links, const Eigen::Vector3d& top, double length, double mass, std::vector<BodySpec>& bodies,
              std::vector<JointSpec>& joints) {
  Eigen::Vector3d at = top;
  std::string previous = "world";
  for (int i = 0; i < links; ++i) {
    const std::string name = "link" + std::to_string(i);
    bodies.push_back(rod(name, at, M_PI / 2, length, 0.02, mass));
    joints.push_back(joint(JointType::Ball, previous, name, at));
    at = rodEnd(at, M_PI / 2, length);
    previous = name;
  }
}

JointRun makeRun(std::vector<BodySpec> bodies, std::vector<JointSpec> joints, ContactModel model, double dt,
                 const Eigen::Vector3d& gravity) {
  Scene scene;
  scene.bodies = std::move(bodies);
  scene.joints = std::move(joints);
  scene.simulation.gravity_m_s2 = gravity;
  scene.simulation.step.model = model;
  scene.simulation.step.dt = dt;
  scene.simulation.step.sleep.enabled = false;
  JointRun run{buildWorld(scene), {}};
  run.step = run.built.step;
  return run;
}

void simulate(JointRun& run, double seconds, const std::function<void(const World&)>& after) {
  World& world = run.built.world;
  Pipeline pipeline(world, run.step);
  const long steps = std::lround(seconds / run.step.dt);
  for (long i = 0; i < steps; ++i) {
    pipeline.step(world, run.step);
    world.time = double(i + 1) * run.step.dt;   // as the simulator keeps it: exact, not a running sum
    after(world);
  }
}

double totalEnergy(const World& world) {
  double e = 0;
  for (const RigidBody& b : world.bodies)
    if (!b.is_static) e += b.kineticEnergy() - b.mass * world.gravity.dot(b.x);
  return e;
}

}  // namespace tumble::joint_test
