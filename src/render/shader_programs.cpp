#include "render/shader_programs.h"

#include <string>

namespace tumble::render {

namespace {

std::string definesFor(const LightingVariant& v) {
  // GLSL has no zero-length arrays, so the uniform arrays keep at least one element.
  return "#define TUMBLE_LIGHT_COUNT " + std::to_string(v.lights) + "\n" +
         "#define TUMBLE_LIGHT_ARRAY_SIZE " + std::to_string(v.lights > 0 ? v.lights : 1) + "\n" +
         "#define TUMBLE_SHADOWS " + (v.shadows ? "1" : "0") + "\n";
}

}  // namespace

ShaderPrograms::ShaderPrograms(std::filesystem::path dir) : source_(std::move(dir)) {
  // One light with shadows is the usual scene; building it now also validates the files.
  lit(LightingVariant{});
  ground(LightingVariant{});
  shadow_ = std::make_unique<GlProgram>(source_, ShaderStageFiles{"shadow.vert", {}},
                                        ShaderStageFiles{"shadow.frag", {}});
}

const GlProgram& ShaderPrograms::marks() {
  if (!marks_)
    marks_ = std::make_unique<GlProgram>(source_, ShaderStageFiles{"marks.vert", {}}, ShaderStageFiles{"marks.frag", {}});
  return *marks_;
}

const GlProgram& ShaderPrograms::get(Cache& cache, const char* name,
                                     const LightingVariant& variant) {
  auto it = cache.find(variant);
  if (it == cache.end()) {
    const std::string stem = name;
    auto program = std::make_unique<GlProgram>(
        source_, ShaderStageFiles{stem + ".vert", {}},
        ShaderStageFiles{stem + ".frag", {"lighting.glsl"}}, definesFor(variant));
    it = cache.emplace(variant, std::move(program)).first;
  }
  return *it->second;
}

}  // namespace tumble::render
