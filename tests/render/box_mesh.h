// A box as a DrawMesh, for render tests (the product's meshes come from src/geometry).
#pragma once

#include <array>

#include "render/draw_list.h"

namespace tumble::test {

inline DrawMesh boxMesh(const Eigen::Vector3f& half) {
  DrawMesh mesh;
  // Each face: outward normal axis, then two in-face axes ordered so (u, v, n) is right-handed,
  // which makes the corner order below counter-clockwise seen from outside.
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {-1.0f, 1.0f}) {
      Eigen::Vector3f n = Eigen::Vector3f::Zero();
      n[axis] = sign;
      Eigen::Vector3f u = Eigen::Vector3f::Zero(), v = Eigen::Vector3f::Zero();
      u[(axis + 1) % 3] = 1;
      v = n.cross(u);
      const Eigen::Vector3f c = n.cwiseProduct(half);
      const Eigen::Vector3f du = u.cwiseProduct(half), dv = v.cwiseProduct(half);
      const std::array<Eigen::Vector3f, 4> q = {c - du - dv, c + du - dv, c + du + dv,
                                                c - du + dv};
      for (int t : {0, 2}) {
        mesh.positions.push_back(q[0]);
        mesh.positions.push_back(q[t == 0 ? 1 : 2]);
        mesh.positions.push_back(q[t == 0 ? 2 : 3]);
        mesh.normals.push_back(n);
      }
    }
  }
  return mesh;
}

}  // namespace tumble::test
