#include "scene/world_builder.h"

#include <cstdio>

#include "base/error.h"
#include "dynamics/fault_check.h"
#include "dynamics/start_overlap.h"
#include "geometry/mass_properties.h"
#include "geometry/mesh_import.h"
#include "geometry/primitives.h"
#include "scene/joint_builder.h"

namespace tumble {
namespace {

std::string locate(const Scene& scene, const SourceLocation& at) {
  std::string where = scene.file.string();
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on a chain of string + string.
  if (at.line > 0) {
    where.append(":").append(std::to_string(at.line));
    where.append(":").append(std::to_string(at.column));
  }
  return where.append(": ").append(at.pointer).append(": ");
}

ConvexPiece primitive(const PieceSpec& p) {
  switch (p.shape) {
    case ShapeKind::Sphere: return makeSphere(p.radius_m);
    case ShapeKind::Capsule: return makeCapsule(p.radius_m, p.capsule_length_m);
    case ShapeKind::Cylinder: return makeCylinder(p.radius_m, p.height_m);
    case ShapeKind::Tube: return makeTube(p.radius_m, p.inner_radius_m, p.height_m);
    case ShapeKind::Cone: return makeCone(p.radius_m, p.height_m);
    default: return makeBox(p.box_size_m / 2);
  }
}

// Each piece placed in the body's frame; the mass of the union assumes they do not overlap.
std::vector<ConvexPiece> compoundPieces(const BodySpec& spec) {
  std::vector<ConvexPiece> pieces;
  for (const PieceSpec& p : spec.pieces) {
    pieces.push_back(primitive(p));
    pieces.back().transform(p.orientation.toRotationMatrix(), p.position_m);
  }
  return pieces;
}

std::vector<ConvexPiece> piecesOf(const Scene& scene, const BodySpec& spec,
                                  std::vector<std::string>& warnings) {
  switch (spec.shape) {
    case ShapeKind::Box: return {makeBox(spec.box_size_m / 2)};
    case ShapeKind::Sphere: return {makeSphere(spec.radius_m)};
    case ShapeKind::Capsule: return {makeCapsule(spec.radius_m, spec.capsule_length_m)};
    case ShapeKind::Cylinder: return {makeCylinder(spec.radius_m, spec.height_m)};
    case ShapeKind::Tube: return {makeTube(spec.radius_m, spec.inner_radius_m, spec.height_m)};
    case ShapeKind::Cone: return {makeCone(spec.radius_m, spec.height_m)};
    case ShapeKind::Compound: return compoundPieces(spec);
    case ShapeKind::Plane: return {};
    case ShapeKind::Mesh: break;
  }
  try {
    ImportedPieces imported = importConvexPieces(spec.mesh, spec.mesh_scale);
    for (const std::string& w : imported.warnings)
      warnings.push_back("body \"" + spec.name + "\": " + w);
    return std::move(imported.pieces);
  } catch (const Error& e) {
    throw Error(e.code(), locate(scene, spec.mesh_location) + e.what());
  }
}

// Mass properties put in the principal frame; the body's orientation absorbs the frame's rotation
// so the shape sits exactly where the scene placed it.
void setMassAndFrame(const BodySpec& spec, std::vector<ConvexPiece>& pieces, RigidBody& body) {
  MassProperties mp = massProperties(pieces, spec.density_kg_m3);
  if (spec.mass_kg) {
    double scale = *spec.mass_kg / mp.mass;   // same shape, another density
    mp.mass *= scale;
    mp.inertia *= scale;
  }
  PrincipalFrame frame = principalFrame(mp.inertia);
  for (ConvexPiece& p : pieces) p.transform(frame.rotation.transpose(), -frame.rotation.transpose() * mp.center);
  body.pieces = std::move(pieces);
  body.x = spec.position_m + spec.orientation * mp.center;
  body.q = (spec.orientation * Eigen::Quaterniond(frame.rotation)).normalized();
  body.mass = mp.mass;
  body.inertia_body = frame.moments;
  if (!spec.is_static) {
    body.inv_mass = 1 / mp.mass;
    body.inv_inertia_body = frame.moments.cwiseInverse();
  }
}

RigidBody buildBody(const Scene& scene, const BodySpec& spec, std::vector<std::string>& warnings) {
  RigidBody body;
  body.name = spec.name;
  body.shape = spec.shape;
  body.is_static = spec.is_static;
  body.restitution = spec.restitution;
  body.friction = spec.friction;
  body.youngs_modulus_pa = spec.youngs_modulus_pa;
  body.poisson_ratio = spec.poisson_ratio;
  body.colour_srgb = spec.colour_srgb;
  std::vector<ConvexPiece> pieces = piecesOf(scene, spec, warnings);
  if (spec.shape == ShapeKind::Plane) {
    body.x = spec.position_m;
    return body;
  }
  setMassAndFrame(spec, pieces, body);
  if (!body.is_static) {
    body.P = body.mass * spec.velocity_m_s;
    Eigen::Matrix3d R = body.rotation();
    body.L = R * body.inertia_body.cwiseProduct(R.transpose() * spec.angular_velocity_rad_s);
  }
  return body;
}

std::string metres(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g m", x);
  return buffer;
}

// Bodies that start inside one another (start_overlap.h). The error points at the position of the
// body that moves (of the later one when both do): the one the scene placed into the other.
void reportStartOverlaps(const Scene& scene, BuiltWorld& built) {
  const std::vector<RigidBody>& bodies = built.world.bodies;
  for (const StartOverlap& o :
       findStartOverlaps(built.world, scene.simulation.step.contact.tolerance_m, FaultSettings{}.depth_share)) {
    int placed = bodies[o.b].is_static ? o.a : o.b, other = placed == o.b ? o.a : o.b;
    std::string placed_name = "\"" + bodies[placed].name + "\"", other_name = "\"" + bodies[other].name + "\"";
    if (o.tooDeep())
      throw Error(ExitCode::BadInput,
                  locate(scene, scene.bodies[placed].position_location) + "body " + placed_name +
                      " starts inside body " + other_name + ": they overlap by " + metres(o.depth) +
                      ", more than the " + metres(o.limit) +
                      " (half the thinner piece) a step can push apart; move them apart");
    built.warnings.push_back("bodies " + other_name + " and " + placed_name + " start overlapping by " +
                             metres(o.depth) + "; the first steps push them apart, without a push in velocity");
  }
}

}  // namespace

BuiltWorld buildWorld(const Scene& scene) {
  BuiltWorld out;
  out.world.gravity = scene.simulation.gravity_m_s2;
  out.step = scene.simulation.step;
  out.world.bodies.reserve(scene.bodies.size());
  for (const BodySpec& spec : scene.bodies) out.world.bodies.push_back(buildBody(scene, spec, out.warnings));
  addJoints(scene.joints, out.world);   // before the overlap check: joined bodies do not collide
  reportStartOverlaps(scene, out);
  return out;
}

}  // namespace tumble
