#include "io/provenance.h"

#include <cstdio>
#include <map>

#include "base/fnv1a.h"

namespace tumble {

std::string contentHash(const std::string& text) {
  Fnv1a64 fnv;
  fnv.add(text);
  return fnv.hex();
}

std::vector<PngText> frameText(const Provenance& p, int frame) {
  char time[32];
  // Nine digits: a frame instant is a whole number of steps, and steps are no finer than 1e-6 s.
  std::snprintf(time, sizeof time, "%.9g", (frame - 1) * p.frame_interval_s);
  const std::string prefix = kProvenancePrefix;
  std::vector<PngText> text = {
      {"Software", "tumble " + p.version + " (commit " + p.commit + ")"},
      {prefix + "version", p.version},
      {prefix + "commit", p.commit},
      {prefix + "scene hash", p.scene_hash},
      {prefix + "frame", std::to_string(frame)},
      {prefix + "time s", time},
  };
  if (!p.renderer.empty()) text.push_back({prefix + "renderer", p.renderer});
  return text;
}

namespace {

std::map<std::string, std::string> provenanceOf(const std::vector<PngText>& text) {
  std::map<std::string, std::string> out;
  for (const PngText& t : text)
    if (t.keyword.rfind(kProvenancePrefix, 0) == 0) out[t.keyword] = t.text;
  return out;
}

}  // namespace

std::vector<std::string> provenanceDifferences(const std::vector<PngText>& a, const std::vector<PngText>& b) {
  std::map<std::string, std::string> pa = provenanceOf(a), pb = provenanceOf(b);
  std::vector<std::string> lines;
  if (pa.empty() || pb.empty()) return lines;
  std::map<std::string, std::string> keys = pa;
  keys.insert(pb.begin(), pb.end());
  for (const auto& [key, unused] : keys) {
    auto ia = pa.find(key), ib = pb.find(key);
    const std::string va = ia == pa.end() ? "(none)" : ia->second, vb = ib == pb.end() ? "(none)" : ib->second;
    if (va != vb) lines.push_back("  " + key + ": " + va + " | " + vb);
  }
  return lines;
}

std::vector<std::pair<std::string, std::string>> videoMetadata(const Provenance& p) {
  return {{"comment", "tumble " + p.version + " (commit " + p.commit + "), scene " + p.scene_hash},
          {"tumble_version", p.version},
          {"tumble_commit", p.commit},
          {"tumble_scene_hash", p.scene_hash}};
}

}  // namespace tumble
