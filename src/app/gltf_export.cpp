#include "app/gltf_export.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <tuple>

#include "app/stats_file.h"
#include "io/atomic_file.h"
#include "io/png_bytes.h"

namespace tumble {
namespace {

using json = nlohmann::json;

// glTF 2.0's numbers (Khronos, "glTF 2.0 Specification", 2021, sections 3.6 and 4.4).
constexpr int kFloat = 5126;           // accessor componentType FLOAT
constexpr int kArrayBuffer = 34962;    // bufferView target for vertex attributes
constexpr std::uint32_t kGlbMagic = 0x46546C67, kJsonChunk = 0x4E4F534A, kBinChunk = 0x004E4942;

// The binary buffer and the accessors into it, built side by side.
class GltfBuffers {
 public:
  explicit GltfBuffers(json& doc) : doc_(doc) {}

  // Appends floats (`width` per element: 1 SCALAR, 2 VEC2, 3 VEC3, 4 VEC4) as a bufferView and an
  // accessor over it; returns the accessor's index. POSITION and animation inputs need min/max.
  int add(const std::vector<float>& values, int width, bool vertex, bool bounds) {
    while (bin_.size() % 4) bin_.push_back(0);   // accessors start on 4-byte boundaries
    const std::size_t offset = bin_.size();
    bin_.resize(offset + values.size() * sizeof(float));
    std::memcpy(bin_.data() + offset, values.data(), values.size() * sizeof(float));
    json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * sizeof(float)}};
    if (vertex) view["target"] = kArrayBuffer;
    doc_["bufferViews"].push_back(view);
    static const char* kTypes[] = {"", "SCALAR", "VEC2", "VEC3", "VEC4"};
    json accessor = {{"bufferView", doc_["bufferViews"].size() - 1}, {"componentType", kFloat},
                     {"count", values.size() / width}, {"type", kTypes[width]}};
    if (bounds) {
      std::vector<float> lo(width, INFINITY), hi(width, -INFINITY);
      for (std::size_t i = 0; i < values.size(); ++i) {
        lo[i % width] = std::min(lo[i % width], values[i]);
        hi[i % width] = std::max(hi[i % width], values[i]);
      }
      accessor["min"] = lo;
      accessor["max"] = hi;
    }
    doc_["accessors"].push_back(accessor);
    return static_cast<int>(doc_["accessors"].size() - 1);
  }
  // Appends raw bytes (an embedded image) as a bufferView; returns the view's index.
  int addBytes(const std::vector<std::uint8_t>& bytes) {
    while (bin_.size() % 4) bin_.push_back(0);
    const std::size_t offset = bin_.size();
    bin_.insert(bin_.end(), bytes.begin(), bytes.end());
    doc_["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes.size()}});
    return static_cast<int>(doc_["bufferViews"].size() - 1);
  }
  const std::vector<std::uint8_t>& bin() const { return bin_; }

 private:
  json& doc_;
  std::vector<std::uint8_t> bin_;
};

// A mesh's triangles as glTF attributes: per-vertex normals (a faceted mesh repeats its face's),
// texture coordinates flipped to glTF's v = 0 at the image's top row.
json primitiveOf(const DrawMesh& mesh, GltfBuffers& buffers) {
  std::vector<float> positions, normals, uvs;
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const Eigen::Vector3f& p = mesh.positions[i];
    const Eigen::Vector3f& n = mesh.smooth() ? mesh.normals[i] : mesh.normals[i / 3];
    positions.insert(positions.end(), {p.x(), p.y(), p.z()});
    normals.insert(normals.end(), {n.x(), n.y(), n.z()});
    if (!mesh.uvs.empty()) uvs.insert(uvs.end(), {mesh.uvs[i].x(), 1.0f - mesh.uvs[i].y()});
  }
  json attributes = {{"POSITION", buffers.add(positions, 3, true, true)},
                     {"NORMAL", buffers.add(normals, 3, true, false)}};
  if (!uvs.empty()) attributes["TEXCOORD_0"] = buffers.add(uvs, 2, true, false);
  return {{"attributes", attributes}, {"mode", 4}};   // 4: TRIANGLES
}

// One key per frame. Consecutive quaternions are kept on one hemisphere: q and -q are the same
// turn, and a sign flip between keys would send the interpolation the long way round.
void addAnimation(json& doc, GltfBuffers& buffers, const Trajectory& t, int body, int node, int input) {
  std::vector<float> translation, rotation;
  Eigen::Quaterniond previous = t.frames.front()[body].q;
  for (const std::vector<BodySample>& frame : t.frames) {
    const BodySample& s = frame[body];
    Eigen::Quaterniond q = s.q;
    if (q.dot(previous) < 0) q.coeffs() = -q.coeffs();
    previous = q;
    translation.insert(translation.end(), {float(s.x.x()), float(s.x.y()), float(s.x.z())});
    rotation.insert(rotation.end(), {float(q.x()), float(q.y()), float(q.z()), float(q.w())});
  }
  json& animation = doc["animations"][0];
  for (const auto& [path, values, width] : {std::tuple{"translation", &translation, 3}, {"rotation", &rotation, 4}}) {
    animation["samplers"].push_back(
        {{"input", input}, {"output", buffers.add(*values, width, false, false)}, {"interpolation", "LINEAR"}});
    animation["channels"].push_back(
        {{"sampler", animation["samplers"].size() - 1}, {"target", {{"node", node}, {"path", path}}}});
  }
}

std::vector<std::uint8_t> glb(const json& doc, const std::vector<std::uint8_t>& bin) {
  std::string text = doc.dump();
  while (text.size() % 4) text += ' ';   // chunks are 4-byte aligned: JSON pads with spaces
  std::vector<std::uint8_t> data = bin;
  while (data.size() % 4) data.push_back(0);
  std::vector<std::uint8_t> out;
  auto word = [&](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));   // little-endian
  };
  word(kGlbMagic);
  word(2);
  word(static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + data.size()));
  word(static_cast<std::uint32_t>(text.size()));
  word(kJsonChunk);
  out.insert(out.end(), text.begin(), text.end());
  word(static_cast<std::uint32_t>(data.size()));
  word(kBinChunk);
  out.insert(out.end(), data.begin(), data.end());
  return out;
}

// The glTF texture index of each of the drawing's textures, embedded as PNG in the binary buffer
// on first use (-1: not yet); a texture no exported part uses is left out.
int gltfTexture(json& doc, GltfBuffers& buffers, const SceneDrawing& drawing, int texture,
                std::vector<int>& gltf_texture_of) {
  if (gltf_texture_of[texture] < 0) {
    const int view = buffers.addBytes(encodePngBytes(drawing.textures[texture]));
    doc["images"].push_back({{"bufferView", view}, {"mimeType", "image/png"}});
    doc["textures"].push_back({{"source", doc["images"].size() - 1}});
    gltf_texture_of[texture] = static_cast<int>(doc["textures"].size() - 1);
  }
  return gltf_texture_of[texture];
}

}  // namespace

void checkGltfOutput(const std::filesystem::path& path, bool overwrite) { checkStatsOutput(path, overwrite); }

void writeGltf(const std::filesystem::path& path, bool overwrite, const SceneDrawing& drawing,
               const Trajectory& trajectory) {
  json doc = {{"asset", {{"version", "2.0"}, {"generator", "tumble"}}},
              {"scene", 0},
              {"scenes", {{{"nodes", {0}}}}},
              // -90 degrees about x: tumble's z (up) becomes glTF's y (up).
              {"nodes", {{{"name", "tumble (z up)"}, {"rotation", {-M_SQRT1_2, 0, 0, M_SQRT1_2}}, {"children", json::array()}}}},
              {"meshes", json::array()},
              {"materials", json::array()},
              {"accessors", json::array()},
              {"bufferViews", json::array()},
              {"animations", {{{"name", "simulation"}, {"samplers", json::array()}, {"channels", json::array()}}}}};
  GltfBuffers buffers(doc);
  std::vector<float> times(trajectory.times.begin(), trajectory.times.end());
  const int input = buffers.add(times, 1, false, true);
  std::vector<int> gltf_texture_of(drawing.textures.size(), -1);
  doc["images"] = json::array();
  doc["textures"] = json::array();
  std::vector<json> primitives;
  for (std::size_t m = 0; m < drawing.meshes.size(); ++m) primitives.push_back(primitiveOf(drawing.meshes[m], buffers));
  for (std::size_t b = 0; b < drawing.parts_of_body.size() && b < trajectory.body_names.size(); ++b) {
    if (drawing.parts_of_body[b].empty()) continue;
    json mesh = {{"name", trajectory.body_names[b]}, {"primitives", json::array()}};
    for (const DrawnPart& part : drawing.parts_of_body[b]) {
      // baseColorFactor is linear, as DrawnPart's colour is; a base-colour texture is sRGB, as
      // tumble samples it, and multiplies the factor, as in tumble's shader.
      json pbr = {{"baseColorFactor", {part.colour.x(), part.colour.y(), part.colour.z(), 1.0}},
                  {"metallicFactor", 0.0}, {"roughnessFactor", 0.7}};
      const int texture = drawing.meshes[part.mesh].texture;
      if (texture >= 0 && !drawing.meshes[part.mesh].uvs.empty())
        pbr["baseColorTexture"] = {{"index", gltfTexture(doc, buffers, drawing, texture, gltf_texture_of)}};
      doc["materials"].push_back({{"pbrMetallicRoughness", pbr}});
      json primitive = primitives[part.mesh];
      primitive["material"] = doc["materials"].size() - 1;
      mesh["primitives"].push_back(primitive);
    }
    doc["meshes"].push_back(mesh);
    const int node = static_cast<int>(doc["nodes"].size());
    // The node rests at the first frame's pose, as a tool that ignores the animation shows it.
    const BodySample& first = trajectory.frames.front()[b];
    doc["nodes"].push_back({{"name", trajectory.body_names[b]},
                            {"mesh", doc["meshes"].size() - 1},
                            {"translation", {first.x.x(), first.x.y(), first.x.z()}},
                            {"rotation", {first.q.x(), first.q.y(), first.q.z(), first.q.w()}}});
    doc["nodes"][0]["children"].push_back(node);
    addAnimation(doc, buffers, trajectory, static_cast<int>(b), node, input);
  }
  if (doc["animations"][0]["channels"].empty()) doc.erase("animations");   // glTF wants a channel in each
  if (doc["images"].empty()) {   // glTF wants these arrays absent rather than empty
    doc.erase("images");
    doc.erase("textures");
  }
  doc["buffers"] = {{{"byteLength", buffers.bin().size()}}};
  const std::vector<std::uint8_t> bytes = glb(doc, buffers.bin());
  writeFileWhole(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), overwrite);
}

}  // namespace tumble
