// What the renderer draws, with no GL and no physics in it: the app builds a DrawFrame from the
// simulation's state; the renderer only reads it. float is enough for pictures.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "base/image.h"

namespace tumble {

// How a mesh is shaded. Facets: the normal of each triangle's first corner over the whole
// triangle (convex pieces, the built-in shapes; the look the golden frames pin). Surface: normals
// interpolated across triangles and the albedo read from a texture, for meshes as a file holds them.
enum class MeshShading { Facets, Surface };

// A triangle soup: one normal per triangle (flat shading per convex face), or one per corner (a
// smooth surface: a sphere, a capsule, an imported mesh's own normals).
struct DrawMesh {
  std::vector<Eigen::Vector3f> positions;   // 3 per triangle, counter-clockwise seen from outside
  std::vector<Eigen::Vector3f> normals;     // outward unit: 1 per triangle, or 1 per position
  MeshShading shading = MeshShading::Facets;
  // Surface only: texture coordinates per position (OpenGL's: v = 0 at the image's bottom row),
  // or none; and the albedo texture (an index returned by Renderer::addTexture), or -1 for none.
  // The albedo is the texture's colour times the instance's.
  std::vector<Eigen::Vector2f> uvs;
  int texture = -1;
  bool smooth() const { return !positions.empty() && normals.size() == positions.size(); }
};

// An albedo texture: sRGB-encoded colour (alpha unused: bodies are opaque), top row first.
using DrawTexture = RgbaImage;

struct DrawInstance {
  int mesh = 0;                                       // index returned by Renderer::addMesh
  Eigen::Affine3f model = Eigen::Affine3f::Identity(); // mesh coordinates -> world (rigid)
  Eigen::Vector3f colour{0.8f, 0.8f, 0.8f};           // linear RGB albedo, 0..1
};

// The static ground plane z = height, drawn as a large checkerboard so motion reads.
struct DrawGround {
  bool present = false;
  float height = 0;                                    // m
  Eigen::Vector3f colour_a{0.55f, 0.55f, 0.55f};      // linear RGB
  Eigen::Vector3f colour_b{0.42f, 0.42f, 0.42f};
  float checker_m = 1.0f;                              // checker square edge, m
  float extent_m = 200.0f;                             // half size of the drawn square, m
};

struct DrawCamera {
  Eigen::Vector3f eye{6, -8, 4};
  Eigen::Vector3f target{0, 0, 0.5f};
  Eigen::Vector3f up{0, 0, 1};                         // world z-up
  float fov_y_deg = 45;
  float near_m = 0.05f, far_m = 500;
};

struct DirectionalLight {
  Eigen::Vector3f direction{-0.4f, 0.3f, -1};         // the way the light travels (towards the scene)
  Eigen::Vector3f colour{1, 1, 1};                     // linear RGB
  float intensity = 1;
  bool casts_shadows = true;                           // at most one light casts shadows
};

// Marks laid over the shaded scene by the overlays (src/app/overlay_marks.cpp): segments and dots
// in world space, drawn unlit with a dark outline, after the bodies and the ground and with the
// depth test off, so that a contact between two stacked blocks, hidden inside the stack's
// silhouette, still shows. Widths are in pixels, so marks read the same at any distance.
// Colours are sRGB as written to the frame (no lighting, no tone mapping).
struct DrawSegment {
  Eigen::Vector3f from, to;   // m, world
  Eigen::Vector3f colour;     // sRGB, 0..1
};

struct DrawDot {
  Eigen::Vector3f at;         // m, world
  Eigen::Vector3f colour;     // sRGB, 0..1
};

// A faded line under the marks, thin and without an outline, blended over the frame at `alpha`:
// many of them (a body's edges at every trial of a back-step, every piece's box) would bury the
// scene if drawn as marks.
struct DrawFaintSegment {
  Eigen::Vector3f from, to;   // m, world
  Eigen::Vector3f colour;     // sRGB, 0..1
  float alpha = 0.5f;         // 0..1
};

struct DrawMarks {
  std::vector<DrawSegment> segments;
  std::vector<DrawDot> dots;
  std::vector<DrawFaintSegment> faint;   // drawn first, under every mark
  float line_px = 2;          // segment width
  float dot_px = 6;           // dot diameter
  float outline_px = 1;       // dark rim around each, for contrast on any background
  float faint_px = 1;         // faint lines' width
  bool empty() const { return segments.empty() && dots.empty() && faint.empty(); }
};

struct DrawFrame {
  DrawCamera camera;
  std::vector<DirectionalLight> lights;
  Eigen::Vector3f ambient{0.25f, 0.25f, 0.28f};       // linear RGB added to every surface
  Eigen::Vector3f background{0.62f, 0.72f, 0.85f};    // linear RGB
  DrawGround ground;
  std::vector<DrawInstance> instances;
  DrawMarks marks;                                     // overlays; none by default
};

}  // namespace tumble
