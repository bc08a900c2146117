// The renderer's GLSL programs, in variants compiled on first use. The light count and whether
// shadows are on are compile-time constants of a variant rather than uniforms, because llvmpipe
// runs fragments as SIMD lanes and pays for both sides of every branch and for every trip of a
// loop with a run-time bound: a variant with the light loop unrolled and no dead shadow code was
// measured about twice as fast on the ground (1280x720).
#pragma once

#include <filesystem>
#include <map>
#include <memory>

#include "render/gl_program.h"
#include "render/shader_source.h"

namespace tumble::render {

struct LightingVariant {
  int lights = 1;        // number of directional lights, 0..kMaxLights
  bool shadows = true;   // light 0 casts shadows
  auto operator<=>(const LightingVariant&) const = default;
};

class ShaderPrograms {
 public:
  // Compiles the common variants now, so a missing or broken shader is reported at start-up
  // (Error MissingInput / BadInput, see GlProgram). `dir`: the folder to read the GLSL from;
  // empty for the built-in copy.
  explicit ShaderPrograms(std::filesystem::path dir);

  const GlProgram& lit(const LightingVariant& variant) { return get(lit_, "lit", variant); }
  const GlProgram& ground(const LightingVariant& variant) {
    return get(ground_, "ground", variant);
  }
  // Meshes drawn with MeshShading::Surface: interpolated normals and an albedo texture.
  const GlProgram& surface(const LightingVariant& variant) { return get(surface_, "surface", variant); }
  const GlProgram& shadow() const { return *shadow_; }
  // Overlay marks (marks_pass.h): flat sRGB colour in NDC; compiled on first use.
  const GlProgram& marks();

 private:
  using Cache = std::map<LightingVariant, std::unique_ptr<GlProgram>>;
  const GlProgram& get(Cache& cache, const char* name, const LightingVariant& variant);

  ShaderSource source_;
  Cache lit_, ground_, surface_;
  std::unique_ptr<GlProgram> shadow_, marks_;
};

}  // namespace tumble::render
