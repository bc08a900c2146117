// Off-screen renderer: OSMesa core-profile context, GLSL from shaders/, Blinn-Phong with flat
// normals (or a mesh file's own normals and albedo texture), one shadow-mapped directional light,
// optional 4x MSAA, sRGB (gamma-correct) output.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include "base/image.h"
#include "render/draw_list.h"

namespace tumble {

struct RenderConfig {
  int width = 1280, height = 720;          // pixels
  int samples = 4;                         // MSAA samples: 1 (off) or 4 (llvmpipe's maximum)
  int shadow_map_size = 2048;              // texels per side of the shadow map
  std::filesystem::path shader_dir;        // folder of .vert/.frag files; empty: the built-in copy
};

class Renderer {
 public:
  // Throws tumble::Error(Unavailable) when OSMesa cannot make a context, BadInput/MissingInput
  // when a shader is missing or fails to compile (with the GLSL log).
  static std::unique_ptr<Renderer> create(const RenderConfig& config);
  virtual ~Renderer() = default;

  // Uploads a texture once (mipmapped, sampled as sRGB); meshes refer to it by the returned index.
  // Throws Error(BadInput) for an empty image or one larger than the GL allows.
  virtual int addTexture(const DrawTexture& texture) = 0;
  // Uploads a mesh once; instances refer to it by the returned index. Its texture, if any, must
  // have been added.
  virtual int addMesh(const DrawMesh& mesh) = 0;
  // Renders into the off-screen framebuffer (shadow pass, then the lit pass, then MSAA resolve).
  virtual void draw(const DrawFrame& frame) = 0;
  // Reads the last drawn frame back, flipped so that row 0 is the top.
  virtual void readBack(RgbImage& out) = 0;
};

}  // namespace tumble
