#include "render/instance_data.h"

#include <algorithm>
#include <string>
#include <tuple>

#include "base/error.h"

namespace tumble::render {

namespace {

void checkInstance(const DrawInstance& inst, std::size_t index, int mesh_count) {
  if (inst.mesh < 0 || inst.mesh >= mesh_count) {
    throw Error(ExitCode::BadInput, "draw instance " + std::to_string(index) + " refers to mesh " +
                                        std::to_string(inst.mesh) + " but only " +
                                        std::to_string(mesh_count) + " meshes were added");
  }
  if (!inst.model.matrix().allFinite() || !inst.colour.allFinite()) {
    throw Error(ExitCode::BadInput,
                "draw instance " + std::to_string(index) + " has a non-finite pose or colour");
  }
}

void writeRecord(const DrawInstance& inst, float* rec) {
  const Eigen::Matrix4f& m = inst.model.matrix();
  std::copy(m.data(), m.data() + 16, rec);  // Eigen and GL are both column-major
  rec[16] = inst.colour.x();
  rec[17] = inst.colour.y();
  rec[18] = inst.colour.z();
  rec[19] = 0;
}

}  // namespace

void packInstances(const std::vector<DrawInstance>& instances, int mesh_count,
                   const Eigen::Vector3f& eye, PackedInstances& out) {
  struct Key {
    int mesh;
    float distance2;
    std::size_t index;
    bool operator<(const Key& o) const {
      return std::tie(mesh, distance2, index) < std::tie(o.mesh, o.distance2, o.index);
    }
  };
  std::vector<Key> keys;
  keys.reserve(instances.size());
  for (std::size_t i = 0; i < instances.size(); ++i) {
    checkInstance(instances[i], i, mesh_count);
    keys.push_back({instances[i].mesh, (instances[i].model.translation() - eye).squaredNorm(), i});
  }
  std::sort(keys.begin(), keys.end());

  out.batches.clear();
  out.data.resize(instances.size() * kInstanceFloats);
  for (std::size_t k = 0; k < keys.size(); ++k) {
    writeRecord(instances[keys[k].index], out.data.data() + k * kInstanceFloats);
    if (out.batches.empty() || out.batches.back().mesh != keys[k].mesh) {
      out.batches.push_back({keys[k].mesh, k, 0});
    }
    ++out.batches.back().count;
  }
}

}  // namespace tumble::render
