// Per-frame instance data, packed for instanced drawing: instances grouped by mesh so each mesh
// is one draw call per pass, whatever the number of bodies, and nearest first within a mesh so
// the depth test rejects hidden fragments before they are shaded (llvmpipe skips a block whose
// pixels all fail it). GL-free, so it can be tested alone.
#pragma once

#include <cstddef>
#include <vector>

#include "render/draw_list.h"

namespace tumble::render {

// Floats per instance in the instance buffer: model matrix (16, column-major) + RGB + 1 padding
// so each record is 80 bytes.
constexpr std::size_t kInstanceFloats = 20;

struct InstanceBatch {
  int mesh = 0;
  std::size_t first = 0;  // index of the first instance record of this mesh
  std::size_t count = 0;
};

struct PackedInstances {
  std::vector<float> data;            // kInstanceFloats per instance, batch after batch
  std::vector<InstanceBatch> batches; // in increasing mesh index; meshes with no instance skipped
};

// Order: mesh index, then distance of the instance's origin from `eye`, then draw-list index, a
// total order so the same frame always packs the same bytes. Throws Error(BadInput) for a mesh
// index outside [0, mesh_count) or a non-finite pose.
void packInstances(const std::vector<DrawInstance>& instances, int mesh_count,
                   const Eigen::Vector3f& eye, PackedInstances& out);

}  // namespace tumble::render
