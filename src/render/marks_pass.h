// Draws DrawMarks (draw_list.h) over the finished scene: each segment a quad and each dot an
// octagon of exact pixel size, built on the CPU from the camera's projection, first the faint lines
// blended at their alpha, then every outline in dark grey, then every mark in its colour. The depth test is off: marks sit on surfaces and
// between touching bodies, where a depth test would hide half of them or make them flicker.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "render/draw_list.h"
#include "render/gl_api.h"
#include "render/gl_program.h"

namespace tumble::render {

// Two triangles per segment and six per dot, in NDC, each vertex x, y, r, g, b, a (a < 1 only for
// faint lines). A segment that lies behind the camera is left out, one that crosses the near plane
// is cut at it.
void buildMarkTriangles(const DrawMarks& marks, const Eigen::Matrix4f& view_proj, int width, int height,
                        std::vector<float>& out);

class MarksPass {
 public:
  MarksPass();
  ~MarksPass();
  MarksPass(const MarksPass&) = delete;
  MarksPass& operator=(const MarksPass&) = delete;

  void draw(const DrawMarks& marks, const Eigen::Matrix4f& view_proj, int width, int height,
            const GlProgram& program);

 private:
  GLuint vao_ = 0, vbo_ = 0;
  std::vector<float> vertices_;   // reused each frame
};

}  // namespace tumble::render
