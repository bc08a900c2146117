// FNV-1a, 64 bits (Fowler, Noll and Vo, "FNV hash", IETF draft-eastlake-fnv, 2019): a fingerprint
// that tells one scene or file from another, not a guard against tampering. One definition for
// the scene hash that provenance writes and the motion hash a trajectory carries.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace tumble {

class Fnv1a64 {
 public:
  void add(std::string_view bytes) {
    for (unsigned char c : bytes) addByte(c);
  }
  void addByte(unsigned char c) { h_ = (h_ ^ c) * 1099511628211ull; }
  std::uint64_t value() const { return h_; }
  // 16 hex digits.
  std::string hex() const {
    char out[17];
    std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(h_));
    return out;
  }

 private:
  std::uint64_t h_ = 14695981039346656037ull;   // the offset basis
};

}  // namespace tumble
