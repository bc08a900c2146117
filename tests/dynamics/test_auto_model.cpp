// The automatic contact model (dynamics/auto/auto_model.h): which model it runs for which scene,
// that it says so, and that it is exactly the model it chose (bit for bit).
#include <catch2/catch.hpp>

#include <cstring>

#include "dynamics/auto/auto_model.h"
#include "dynamics/pipeline.h"
#include "scene/world_builder.h"

using namespace tumble;

namespace {

// `free_boxes` 0.2 m boxes in a row, 1 m up and apart, and `stacked` more stacked on the ground.
World boxes(int free_boxes, int stacked) {
  Scene scene;
  BodySpec ground;
  ground.name = "ground";
  ground.shape = ShapeKind::Plane;
  ground.is_static = true;
  scene.bodies.push_back(ground);
  for (int i = 0; i < free_boxes + stacked; ++i) {
    BodySpec b;
    b.name = "box_" + std::to_string(i);
    b.box_size_m = {0.2, 0.2, 0.2};
    const bool is_free = i < free_boxes;
    b.position_m = is_free ? Eigen::Vector3d(0.5 * i, 0, 1) : Eigen::Vector3d(-3, 0, 0.1 + 0.2 * (i - free_boxes));
    b.orientation = is_free ? Eigen::Quaterniond(Eigen::AngleAxisd(0.1 * i, Eigen::Vector3d::UnitX())) : Eigen::Quaterniond::Identity();
    scene.bodies.push_back(b);
  }
  return buildWorld(scene).world;
}

StepSettings withModel(ContactModel model) {
  StepSettings s;
  s.model = model;
  return s;
}

// The state of every body after `steps` steps, as bytes.
std::vector<double> run(World world, const StepSettings& settings, int steps) {
  Pipeline pipeline(world, settings);
  for (int k = 0; k < steps; ++k) pipeline.step(world, settings);
  std::vector<double> out;
  for (const RigidBody& b : world.bodies) {
    for (int i = 0; i < 3; ++i) out.insert(out.end(), {b.x[i], b.P[i], b.L[i]});
    out.insert(out.end(), {b.q.w(), b.q.x(), b.q.y(), b.q.z()});
  }
  return out;
}

}  // namespace

TEST_CASE("auto: a crowd of 20 free bodies runs by time stepping and 19 by Baraff, and it says why", "[auto]") {
  const World crowd = boxes(kAutoCrowd, 0), few = boxes(kAutoCrowd - 1, 0);
  const StepSettings s = withModel(ContactModel::Auto);
  Pipeline a(crowd, s), b(few, s);
  CHECK(a.runningModel(s) == ContactModel::TimeStepping);
  CHECK(b.runningModel(s) == ContactModel::Baraff);
  CHECK(a.counters().model_choice.find("20 of 20 moving bodies start free") != std::string::npos);
  CHECK(b.counters().model_choice.find("auto chose Baraff") != std::string::npos);
  CHECK(a.describe(s).front().find("auto chose time stepping") != std::string::npos);
}

TEST_CASE("auto: bodies that start resting are no crowd, and a restitution law only Baraff has keeps Baraff", "[auto]") {
  StepSettings s = withModel(ContactModel::Auto);
  Pipeline stack(boxes(3, 30), s);
  CHECK(stack.runningModel(s) == ContactModel::Baraff);
  s.contact.restitution_law = RestitutionLaw::Poisson;
  Pipeline crowd(boxes(25, 0), s);
  CHECK(crowd.runningModel(s) == ContactModel::Baraff);
  CHECK(crowd.counters().model_choice.find("Poisson") != std::string::npos);
}

TEST_CASE("auto: its run is bit for bit the run of the model it chose", "[auto]") {
  const World few = boxes(5, 3), crowd = boxes(kAutoCrowd, 0);
  CHECK(run(few, withModel(ContactModel::Auto), 120) == run(few, withModel(ContactModel::Baraff), 120));
  CHECK(run(crowd, withModel(ContactModel::Auto), 120) ==
        run(crowd, crowdSettings(withModel(ContactModel::TimeStepping)), 120));
}
