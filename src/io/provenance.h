// Where a frame or a video came from, written into the file itself: the tumble that made it, the
// scene it showed (a hash of the resolved scene, after overrides), and for a PNG the frame, its
// simulated instant and the OpenGL renderer. Two frames that differ can then say why: another
// version, another scene, another renderer.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "io/png_file.h"

namespace tumble {

struct Provenance {
  std::string version, commit;   // of the tumble that wrote it
  std::string scene_hash;        // contentHash of the resolved scene
  std::string renderer;          // GL_RENDERER; empty until the renderer exists
  double frame_interval_s = 0;   // simulated seconds between frames: frame k shows (k - 1) x this
};

// FNV-1a, 64 bits, as 16 hex digits: a fingerprint to tell scenes apart, not a guard against
// tampering (Fowler, Noll and Vo, "FNV hash", IETF draft-eastlake-fnv, 2019).
std::string contentHash(const std::string& text);

// The PNG text chunks of frame `frame`: "Software" (the PNG keyword viewers show), then the
// "tumble ..." keywords below, each value alone so a script can read it back.
std::vector<PngText> frameText(const Provenance& p, int frame);
// frameText's own keywords are this prefix and version, commit, scene hash, frame, time s, renderer.
inline constexpr const char* kProvenancePrefix = "tumble ";

// The provenance keywords (Software and the "tumble ..." ones) whose values differ between two
// frames' text chunks, one line each: "  tumble commit: 1a2b3c4 | 5d6e7f8". Empty when they agree,
// or when either frame carries no provenance (one rendered before frames were stamped).
std::vector<std::string> provenanceDifferences(const std::vector<PngText>& a, const std::vector<PngText>& b);

// A video's container metadata: "comment" (what players show) and tumble_version,
// tumble_commit, tumble_scene_hash.
std::vector<std::pair<std::string, std::string>> videoMetadata(const Provenance& p);

}  // namespace tumble
