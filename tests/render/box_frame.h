// The render tests' usual frame: a red unit box floating 0.5 m above an evenly grey ground (no
// checker, so shadow and lit ground compare fairly), lit from the upper left so its shadow falls
// beside it, towards +x, with slanted edges.
#pragma once

#include "render/draw_list.h"

namespace tumble::test {

inline DrawFrame boxFrame() {
  DrawFrame frame;
  frame.camera.eye = {0, -6, 2};
  frame.camera.target = {0, 0, 1};
  frame.lights.push_back(DirectionalLight{{1, 0.3f, -1}, {1, 1, 1}, 1.0f, true});
  frame.ground.present = true;
  frame.ground.colour_b = frame.ground.colour_a;
  DrawInstance box;
  box.model.translation() = Eigen::Vector3f(0, 0, 1);
  box.colour = {0.8f, 0.05f, 0.05f};
  frame.instances.push_back(box);
  return frame;
}

}  // namespace tumble::test
