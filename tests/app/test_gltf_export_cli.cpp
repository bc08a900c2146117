// simulate --gltf: the motion as an animated glTF 2.0 binary, read back with assimp (the importer
// Blender's users meet in other tools) and compared with the trajectory tumble writes as CSV.
#include <catch2/catch.hpp>

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "run_tumble.h"

using tumble::test::runTumble;
namespace fs = std::filesystem;

namespace {

// A box tossed up with a spin about z, over the ground: it moves and turns in every frame.
const std::string kScene = std::string(TUMBLE_SOURCE_DIR) + "/tests/scenes/small_box.json";

struct Pose {
  double t, x[3], q[4];   // q: w, x, y, z
};

// The box's rows of a trajectory CSV (time,body,px,py,pz,qw,qx,qy,qz,...).
std::vector<Pose> csvPoses(const fs::path& csv, const std::string& body) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<Pose> out;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::string t, name, value;
    std::getline(row, t, ',');
    std::getline(row, name, ',');
    if (name != body) continue;
    Pose p{std::stod(t), {}, {}};
    for (double& x : p.x) std::getline(row, value, ','), x = std::stod(value);
    for (double& q : p.q) std::getline(row, value, ','), q = std::stod(value);
    out.push_back(p);
  }
  return out;
}

// The angle of the turn between two unit quaternions (w, x, y, z), either sign: 2 asin |vector
// part of a* b|, well conditioned near zero where acos is not.
double angleBetween(const double a[4], const aiQuaternion& b) {
  const double w = a[0] * b.w + a[1] * b.x + a[2] * b.y + a[3] * b.z;
  const double x = a[0] * b.x - a[1] * b.w - a[2] * b.z + a[3] * b.y;
  const double y = a[0] * b.y + a[1] * b.z - a[2] * b.w - a[3] * b.x;
  const double z = a[0] * b.z - a[1] * b.y + a[2] * b.x - a[3] * b.w;
  (void)w;
  return 2 * std::asin(std::min(1.0, std::sqrt(x * x + y * y + z * z)));
}

}  // namespace

TEST_CASE("the glTF's node transforms match the trajectory at every key to 1e-6 m and 1e-6 rad", "[cli][gltf]") {
  fs::path dir = tumble::test::freshTempDir("tumble_gltf_keys");
  auto r = runTumble("simulate -q " + kScene + " --trajectory " + (dir / "t.csv").string() + " --gltf " +
                     (dir / "m.glb").string());
  REQUIRE(r.exit_code == 0);
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile((dir / "m.glb").string(), 0);
  INFO(importer.GetErrorString());
  REQUIRE(scene);
  REQUIRE(scene->mNumAnimations == 1);
  const aiAnimation* animation = scene->mAnimations[0];
  const aiNodeAnim* box = nullptr;
  for (unsigned c = 0; c < animation->mNumChannels; ++c)
    if (std::string(animation->mChannels[c]->mNodeName.C_Str()) == "box") box = animation->mChannels[c];
  REQUIRE(box);
  const std::vector<Pose> poses = csvPoses(dir / "t.csv", "box");
  REQUIRE(poses.size() == 10);
  REQUIRE(box->mNumPositionKeys == 10);
  REQUIRE(box->mNumRotationKeys == 10);
  const double ticks = animation->mTicksPerSecond > 0 ? animation->mTicksPerSecond : 1;
  for (int k : {0, 3, 6, 9}) {
    const aiVectorKey& p = box->mPositionKeys[k];
    CHECK(p.mTime / ticks == Approx(poses[k].t).margin(1e-6));
    for (int i = 0; i < 3; ++i) CHECK(std::abs(p.mValue[i] - poses[k].x[i]) < 1e-6);
    CHECK(angleBetween(poses[k].q, box->mRotationKeys[k].mValue) < 1e-6);
  }
  // The box turns: its last key is not its first (a test of keys that never change would pass).
  CHECK(angleBetween(poses[0].q, box->mRotationKeys[9].mValue) > 0.1);
}

TEST_CASE("the glTF holds a node per drawn body with its mesh and colour, under a z-up root", "[cli][gltf]") {
  fs::path dir = tumble::test::freshTempDir("tumble_gltf_nodes");
  REQUIRE(runTumble("simulate -q " + kScene + " --gltf " + (dir / "m.glb").string()).exit_code == 0);
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile((dir / "m.glb").string(), 0);
  REQUIRE(scene);
  const aiNode* box = scene->mRootNode->FindNode("box");
  REQUIRE(box);
  CHECK(scene->mRootNode->FindNode("ground") == nullptr);   // the plane draws as the ground, no mesh
  REQUIRE(box->mNumMeshes == 1);
  const aiMesh* mesh = scene->mMeshes[box->mMeshes[0]];
  CHECK(mesh->mNumFaces == 12);   // a box: 6 faces of 2 triangles
  aiColor4D colour;
  REQUIRE(scene->mMaterials[mesh->mMaterialIndex]->Get(AI_MATKEY_BASE_COLOR, colour) == aiReturn_SUCCESS);
  CHECK(colour.r > colour.b);   // the box is orange (#e04010)
  // The root turns z up into y up: glTF's convention, so Blender stands the scene upright.
  const aiNode* root = box->mParent;
  aiVector3D up = root->mTransformation * aiVector3D(0, 0, 1);
  CHECK(up.y == Approx(1).margin(1e-6));
}

TEST_CASE("a textured body's base-colour texture is embedded in the glTF", "[cli][gltf]") {
  fs::path dir = tumble::test::freshTempDir("tumble_gltf_texture");
  const std::string scene = std::string(TUMBLE_SOURCE_DIR) + "/tests/scenes/visual_textured_gltf.json";
  REQUIRE(runTumble("simulate -q " + scene + " --gltf " + (dir / "m.glb").string()).exit_code == 0);
  Assimp::Importer importer;
  const aiScene* out = importer.ReadFile((dir / "m.glb").string(), 0);
  REQUIRE(out);
  const aiNode* box = out->mRootNode->FindNode("box");
  REQUIRE(box);
  REQUIRE(box->mNumMeshes == 1);
  const aiMesh* mesh = out->mMeshes[box->mMeshes[0]];
  CHECK(mesh->HasTextureCoords(0));
  aiString path;
  REQUIRE(out->mMaterials[mesh->mMaterialIndex]->GetTexture(aiTextureType_BASE_COLOR, 0, &path) == aiReturn_SUCCESS);
  // Embedded, not a file beside it: assimp names embedded textures "*N".
  const aiTexture* texture = out->GetEmbeddedTexture(path.C_Str());
  REQUIRE(texture);
  CHECK(texture->mHeight == 0);   // compressed (a PNG), mWidth bytes long
  CHECK(texture->CheckFormat("png"));
  const auto* bytes = reinterpret_cast<const unsigned char*>(texture->pcData);
  REQUIRE(texture->mWidth > 8);
  CHECK(bytes[1] == 'P');
  CHECK(bytes[2] == 'N');
  CHECK(bytes[3] == 'G');
}

TEST_CASE("an existing glTF is refused (73) unless -y", "[cli][gltf]") {
  fs::path dir = tumble::test::freshTempDir("tumble_gltf_exists");
  std::ofstream(dir / "m.glb") << "precious";
  CHECK(runTumble("simulate -q " + kScene + " --gltf " + (dir / "m.glb").string()).exit_code == 73);
  CHECK(fs::file_size(dir / "m.glb") == 8);
  CHECK(runTumble("simulate -q -y " + kScene + " --gltf " + (dir / "m.glb").string()).exit_code == 0);
  CHECK(fs::file_size(dir / "m.glb") > 1000);
}
