#include "scene/body_reader.h"

#include <cmath>
#include <fstream>

#include "base/error.h"
#include "scene/suggest.h"

namespace tumble {
namespace {

// m: the sizes a double-precision contact solver resolves; meshes are held to the same (mesh_import).
const Range kSize{1e-6, 1e6};

Eigen::Quaterniond eulerExtrinsic(const Eigen::Vector3d& deg, const std::string& order) {
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  // Extrinsic rotations apply in the order written, each about a fixed world axis, so each one
  // multiplies on the left: "XYZ" gives Rz * Ry * Rx.
  for (char axis : order) {
    int i = axis - 'X';
    Eigen::Vector3d unit = Eigen::Vector3d::Unit(i);
    q = Eigen::Quaterniond(Eigen::AngleAxisd(deg[i] * M_PI / 180.0, unit)) * q;
  }
  return q;
}

// The size fields of a primitive (a body's, or a compound's piece's): each shape reads its own, so
// a field of another shape is reported as unknown.
template <class Spec>
void readPrimitiveSize(ObjectReader& in, const std::string& shape, Spec& spec) {
  if (shape == "box") {
    spec.shape = ShapeKind::Box;
    spec.box_size_m = in.vector3("size_m", spec.box_size_m, kSize);
  } else if (shape == "sphere") {
    spec.shape = ShapeKind::Sphere;
    spec.radius_m = in.number("radius_m", spec.radius_m, kSize);
  } else if (shape == "capsule") {
    spec.shape = ShapeKind::Capsule;
    spec.radius_m = in.number("radius_m", spec.radius_m, kSize);
    spec.capsule_length_m = in.number("length_m", spec.capsule_length_m, {0, 1e6});
  } else if (shape == "cylinder" || shape == "cone") {
    spec.shape = shape == "cylinder" ? ShapeKind::Cylinder : ShapeKind::Cone;
    spec.radius_m = in.number("radius_m", spec.radius_m, kSize);
    spec.height_m = in.number("height_m", spec.height_m, kSize);
  } else if (shape == "tube") {
    spec.shape = ShapeKind::Tube;
    spec.radius_m = in.number("radius_m", spec.radius_m, kSize);
    spec.inner_radius_m = in.number("inner_radius_m", 0.8 * spec.radius_m, {0, 1e6});
    if (spec.inner_radius_m >= spec.radius_m)
      in.fail("inner_radius_m", "a tube's bore (" + formatNumber(spec.inner_radius_m) +
                                    " m) must be narrower than its radius (" + formatNumber(spec.radius_m) + " m)");
    spec.height_m = in.number("height_m", spec.height_m, kSize);
  }
}

const std::vector<std::string> kPrimitives{"box", "sphere", "capsule", "cylinder", "tube", "cone"};

// A compound body: primitives placed in the body's frame ("pieces": [{"shape": ..., "position_m":
// ..., "rotation_deg" or "quat_wxyz": ...}, ...]), one convex piece each.
void readPieces(ObjectReader& in, BodySpec& body) {
  const nlohmann::json* list = in.optionalArray("pieces");
  if (list->empty()) in.fail("pieces", "a compound body needs at least one piece");
  body.shape = ShapeKind::Compound;
  for (std::size_t i = 0; i < list->size(); ++i) {
    ObjectReader p = in.element("pieces", i);
    PieceSpec piece;
    readPrimitiveSize(p, readChoice(p, "shape", "box", kPrimitives), piece);
    piece.position_m = p.vector3("position_m", piece.position_m);
    piece.orientation = readOrientation(p);
    p.rejectUnknownKeys();
    body.pieces.push_back(piece);
  }
}

void readShape(ObjectReader& in, BodySpec& body, const std::filesystem::path& scene_dir) {
  auto mesh = in.optionalString("mesh");
  std::vector<std::string> shapes = kPrimitives;
  shapes.push_back("plane");
  auto shape = in.has("shape") ? std::optional(readChoice(in, "shape", "", shapes)) : std::nullopt;
  const bool compound = in.has("pieces");
  if (mesh && shape) in.fail("shape", "give either \"mesh\" or \"shape\", not both");
  if (compound && (mesh || shape))
    in.fail("pieces", "give \"pieces\" (a compound body) or \"" + std::string(mesh ? "mesh" : "shape") + "\", not both");
  if (!mesh && !shape && !compound)
    in.fail("", "a body needs \"mesh\" (a file path), \"shape\" (\"box\", \"sphere\", \"capsule\", \"cylinder\", "
                "\"tube\", \"cone\" or \"plane\") or \"pieces\" (a compound of those)");
  if (compound) {
    readPieces(in, body);
  } else if (mesh) {
    checkPathText(in, "mesh", *mesh);
    body.shape = ShapeKind::Mesh;
    body.mesh = (scene_dir / *mesh).lexically_normal();
    body.mesh_location = in.locationOf("mesh");
    std::ifstream probe(body.mesh, std::ios::binary);
    if (!std::filesystem::is_regular_file(body.mesh) || !probe) {
      try {
        in.fail("mesh", "cannot read mesh file " + body.mesh.string());
      } catch (const Error& e) {
        throw Error(ExitCode::MissingInput, e.what());
      }
    }
    body.mesh_scale = in.number("scale", 1, {0, 1e6, true, false});
  } else if (*shape == "plane") {
    body.shape = ShapeKind::Plane;
  } else {
    readPrimitiveSize(in, *shape, body);
  }
  if (body.shape != ShapeKind::Mesh && body.shape != ShapeKind::Plane && body.shape != ShapeKind::Box)
    body.subdivisions = in.integer("subdivisions", body.subdivisions, 1, 6);
}

void readMotionAndMass(ObjectReader& in, BodySpec& body) {
  body.is_static = in.boolean("static", body.shape == ShapeKind::Plane);
  if (body.shape == ShapeKind::Plane && !body.is_static)
    in.fail("static", "a plane is the static ground; it cannot move");
  body.position_m = in.vector3("position_m", body.position_m);
  body.position_location = in.locationOf("position_m");   // for errors found once built (start_overlap.h)
  if (body.shape == ShapeKind::Plane) {
    if (in.has("quat_wxyz") || in.has("rotation_deg"))
      in.fail(in.has("quat_wxyz") ? "quat_wxyz" : "rotation_deg",
              "the ground plane is horizontal (normal +z); it takes no rotation");
  } else {
    body.orientation = readOrientation(in);
  }
  body.velocity_m_s = in.vector3("velocity_m_s", body.velocity_m_s, {-1e5, 1e5});
  body.angular_velocity_rad_s =
      in.vector3("angular_velocity_rad_s", body.angular_velocity_rad_s, {-1e5, 1e5});
  if (body.is_static && (body.velocity_m_s.norm() > 0 || body.angular_velocity_rad_s.norm() > 0))
    in.fail(in.has("velocity_m_s") ? "velocity_m_s" : "angular_velocity_rad_s",
            "a static body cannot have a velocity");
  // Bounded so that 1/m and 1/I stay far from overflow: a milligram to a billion tonnes, and
  // densities from a thin gas to well past osmium (22590 kg/m^3).
  body.mass_kg = in.optionalNumber("mass_kg", {0, 1e12, true, false});
  body.density_kg_m3 = in.number("density_kg_m3", body.density_kg_m3, {0, 1e6, true, false});
  if (body.mass_kg && in.has("density_kg_m3"))
    in.fail("density_kg_m3", "give either \"mass_kg\" or \"density_kg_m3\", not both");
}

}  // namespace

void checkPathText(ObjectReader& in, const std::string& key, const std::string& path) {
  // A NUL ends the path early for the operating system; other control characters are typos at
  // best. Either way the file opened would not be the one the text shows.
  for (unsigned char c : path)
    if (c < 0x20 || c == 0x7f) in.fail(key, "a path cannot contain control characters");
}

std::string readChoice(ObjectReader& in, const std::string& key, const std::string& fallback,
                       const std::vector<std::string>& choices) {
  std::string value = in.string(key, fallback);
  for (const std::string& c : choices)
    if (c == value) return value;
  std::string list;
  for (const std::string& c : choices) list += (list.empty() ? "\"" : ", \"") + c + "\"";
  std::string message = "\"" + value + "\" is not one of " + list;
  std::string near = closestMatch(value, choices);
  if (!near.empty()) message += "; did you mean \"" + near + "\"?";
  in.fail(key, message);
}

BodyDraw readBodyDraw(ObjectReader& in, BodyDraw fallback) {
  return readChoice(in, "draw", fallback == BodyDraw::Hulls ? "hulls" : "visual", {"visual", "hulls"}) == "hulls"
             ? BodyDraw::Hulls
             : BodyDraw::Visual;
}

Integrator readIntegrator(ObjectReader& in, const std::string& key, Integrator fallback) {
  std::string name = readChoice(in, key, fallback == Integrator::Rk4 ? "rk4" : "semi_implicit_euler",
                                {"rk4", "semi_implicit_euler"});
  return name == "rk4" ? Integrator::Rk4 : Integrator::SemiImplicitEuler;
}

Eigen::Quaterniond readOrientation(ObjectReader& in) {
  auto quat = in.optionalVector("quat_wxyz", 4, {-1e6, 1e6});
  auto euler = in.optionalVector("rotation_deg", 3, {-1e6, 1e6});
  bool has_order = in.has("rotation_order");
  std::string order = readChoice(in, "rotation_order", "XYZ", {"XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX"});
  if (quat && euler) in.fail("rotation_deg", "give either \"quat_wxyz\" or \"rotation_deg\", not both");
  if (has_order && !euler) in.fail("rotation_order", "\"rotation_order\" goes with \"rotation_deg\"");
  if (quat) {
    Eigen::Quaterniond q((*quat)[0], (*quat)[1], (*quat)[2], (*quat)[3]);
    if (q.norm() < 1e-12) in.fail("quat_wxyz", "a rotation quaternion cannot be zero");
    return q.normalized();
  }
  if (euler) return eulerExtrinsic(*euler, order).normalized();
  return Eigen::Quaterniond::Identity();
}

BodySpec readBody(ObjectReader& in, int index, const std::filesystem::path& scene_dir) {
  BodySpec body;
  body.name = in.string("name", "body_" + std::to_string(index));
  if (body.name.empty()) in.fail("name", "a body's name cannot be empty");
  readShape(in, body, scene_dir);
  readMotionAndMass(in, body);
  body.restitution = in.number("restitution", body.restitution, {0, 1});
  body.friction = in.number("friction", body.friction, {0, 100});
  body.youngs_modulus_pa = in.number("youngs_modulus_pa", body.youngs_modulus_pa, {0, 1e13, true, false});
  body.poisson_ratio = in.number("poisson_ratio", body.poisson_ratio, {-1, 0.5, true, true});
  if (in.has("color") && in.has("colour")) in.fail("colour", "give \"color\" or \"colour\", not both");
  // The ground defaults to a neutral grey; bodies to a warm orange that reads against it.
  Eigen::Vector3d fallback = body.shape == ShapeKind::Plane ? Eigen::Vector3d(0.62, 0.62, 0.62) : body.colour_srgb;
  body.colour_srgb = in.colour("color", in.colour("colour", fallback));
  body.colour_given = in.has("color") || in.has("colour");
  if (in.has("draw")) {
    if (body.shape == ShapeKind::Plane) in.fail("draw", "the ground plane is drawn as a checkerboard; it takes no \"draw\"");
    body.draw = readBodyDraw(in, BodyDraw::Visual);
  }
  in.rejectUnknownKeys();
  return body;
}

}  // namespace tumble
