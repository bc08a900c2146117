#include "scene/joint_reader.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "scene/body_reader.h"
#include "scene/suggest.h"

namespace tumble {
namespace {

constexpr double kDeg = M_PI / 180;
const char* const kWorld = "world";

// One of "bodies": a body's name or "world", with "did you mean" for a near miss.
std::string readBodyName(const ParseContext& ctx, const nlohmann::json& value, const std::string& pointer,
                         const Scene& scene) {
  if (!value.is_string()) failAt(ctx, pointer, "expected a body's name (a string), got " + describeType(value));
  const std::string name = value.get<std::string>();
  if (name == kWorld) return name;
  std::vector<std::string> names{kWorld};
  for (const BodySpec& b : scene.bodies) {
    if (b.name == name) return name;
    names.push_back(b.name);
  }
  std::string message = "no body is named \"" + name + "\"";
  const std::string near = closestMatch(name, names);
  if (!near.empty()) message += "; did you mean \"" + near + "\"?";
  else message += " (a joint joins two bodies of \"bodies\", or a body and \"world\")";
  failAt(ctx, pointer, message);
}

const BodySpec* bodyNamed(const Scene& scene, const std::string& name) {
  for (const BodySpec& b : scene.bodies)
    if (b.name == name) return &b;
  return nullptr;
}

void readBodies(ObjectReader& in, const ParseContext& ctx, const Scene& scene, JointSpec& joint) {
  const nlohmann::json* list = in.optionalArray("bodies");
  if (!list) in.fail("", "a joint needs \"bodies\": the two bodies it joins, [\"a\", \"b\"] (\"world\" for one of them)");
  if (list->size() != 2)
    in.fail("bodies", "a joint joins two bodies, [\"a\", \"b\"] (\"world\" for one of them); this names " +
                          std::to_string(list->size()));
  const std::string at = in.pointerOf("bodies");
  joint.body_a = readBodyName(ctx, (*list)[0], at + "/0", scene);
  joint.body_b = readBodyName(ctx, (*list)[1], at + "/1", scene);
  if (joint.body_a == joint.body_b)
    failAt(ctx, at + "/1", "a joint joins two different bodies (both are \"" + joint.body_a + "\")");
  auto fixed = [&](const std::string& name) {
    const BodySpec* b = bodyNamed(scene, name);
    return !b || b->is_static || b->shape == ShapeKind::Plane;
  };
  if (fixed(joint.body_a) && fixed(joint.body_b))
    in.fail("bodies", "neither \"" + joint.body_a + "\" nor \"" + joint.body_b +
                          "\" can move (the world, a plane or a static body): the joint would hold nothing");
}

void readMotor(ObjectReader& m, JointMotor& motor) {
  const bool position = m.has("target_deg"), velocity = m.has("target_velocity_deg_s");
  if (position && velocity)
    m.fail("target_velocity_deg_s", "a motor drives to an angle (\"target_deg\", \"kp\", \"kd\") or at a speed "
                                    "(\"target_velocity_deg_s\", \"max_torque_n_m\"), not both");
  if (!position && !velocity)
    m.fail("", "a motor needs \"target_deg\" with \"kp\" and \"kd\" (PD control), or \"target_velocity_deg_s\" "
               "with \"max_torque_n_m\"");
  if (position) {
    motor.kind = JointMotor::Kind::Position;
    motor.target_rad = m.number("target_deg", 0, {-180, 180}) * kDeg;
    if (!m.has("kp")) m.fail("", "a PD motor needs \"kp\" (N m/rad), the stiffness that pulls it to its target");
    motor.kp = m.number("kp", 0, {0, 1e9, true, false});
    motor.kd = m.number("kd", 0, {0, 1e9});
  } else {
    motor.kind = JointMotor::Kind::Velocity;
    motor.target_velocity_rad_s = m.number("target_velocity_deg_s", 0, {-1e6, 1e6}) * kDeg;
    if (!m.has("max_torque_n_m"))
      m.fail("", "a velocity motor needs \"max_torque_n_m\", the most torque it may use to hold its speed");
    motor.max_torque_n_m = m.number("max_torque_n_m", 0, {0, 1e9, true, false});
  }
  m.rejectUnknownKeys();
}

JointSpec readJoint(ObjectReader& in, const ParseContext& ctx, const Scene& scene) {
  JointSpec joint;
  joint.name = in.string("name", "");
  if (!in.has("type")) in.fail("", "a joint needs \"type\": \"ball\", \"hinge\" or \"fixed\"");
  const std::string type = readChoice(in, "type", "ball", {"ball", "hinge", "fixed"});
  joint.type = type == "hinge" ? JointType::Hinge : type == "fixed" ? JointType::Fixed : JointType::Ball;
  readBodies(in, ctx, scene, joint);
  if (!in.has("anchor_m")) {
    // "anchr_m" is better answered with "did you mean": every key a joint may have is asked first.
    for (const char* key : {"axis", "limits_deg", "motor"}) in.has(key);
    in.rejectUnknownKeys();
    in.fail("", "a joint needs \"anchor_m\": the world point [x, y, z] where it joins the bodies");
  }
  joint.anchor_m = in.vector3("anchor_m", joint.anchor_m);
  const bool hinge = joint.type == JointType::Hinge;
  for (const char* key : {"axis", "limits_deg", "motor"})
    if (!hinge && in.has(key))
      in.fail(key, "a " + type + " joint has no \"" + key + "\" (only a hinge has an axis, limits and a motor)");
  if (hinge) {
    if (!in.has("axis")) in.fail("", "a hinge needs \"axis\": the world direction [x, y, z] it turns about");
    const Eigen::Vector3d axis = in.vector3("axis", joint.axis);
    if (!(axis.norm() > 1e-9)) in.fail("axis", "the axis has zero length; give the direction the hinge turns about");
    joint.axis = axis.normalized();
    if (auto limits = in.optionalVector("limits_deg", 2, {-180, 180})) {
      if ((*limits)[0] > (*limits)[1])
        in.fail("limits_deg", "the lower limit (" + formatNumber((*limits)[0]) + " deg) is above the upper (" +
                                  formatNumber((*limits)[1]) + " deg); give [lo, hi]");
      if ((*limits)[0] > 0 || (*limits)[1] < 0)
        in.fail("limits_deg", "the hinge starts at 0 deg, outside [" + formatNumber((*limits)[0]) + ", " +
                                  formatNumber((*limits)[1]) + "]; the limits must hold the starting pose");
      joint.limits_deg = Eigen::Vector2d((*limits)[0], (*limits)[1]);
    }
    if (auto motor = in.optionalObject("motor")) readMotor(*motor, joint.motor);
  }
  in.rejectUnknownKeys();
  return joint;
}

}  // namespace

void readJoints(ObjectReader& root, const ParseContext& ctx, Scene& scene) {
  const nlohmann::json* list = root.optionalArray("joints");
  if (!list) return;
  if (scene.simulation.step.model == ContactModel::Penalty && !list->empty())
    root.fail("joints", "the penalty contact model does not simulate joints; use \"contact_model\": \"baraff\" or "
                        "\"time_stepping\" (or \"auto\") for a scene with joints");
  if (bodyNamed(scene, kWorld))
    root.fail("joints", "a body is named \"world\", which in a joint means the fixed world; rename the body");
  std::set<std::string> names;
  for (std::size_t i = 0; i < list->size(); ++i) {
    ObjectReader in = root.element("joints", i);
    JointSpec joint = readJoint(in, ctx, scene);
    if (!joint.name.empty() && !names.insert(joint.name).second)
      in.fail("name", "another joint is already named \"" + joint.name + "\"");
    scene.joints.push_back(joint);
  }
}

}  // namespace tumble
