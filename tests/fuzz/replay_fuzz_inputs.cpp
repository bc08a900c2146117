// Every input a fuzz target once failed on (fuzz/regressions/TARGET/), and its seeds
// (fuzz/corpus/TARGET/), replayed through the target's own LLVMFuzzerTestOneInput, linked in from
// fuzz/TARGET.cpp: a finding aborts, so a regression fails this test the way it failed the fuzzer.
// TUMBLE_FUZZ_TARGET names the folder (set by CMake).
#include <catch2/catch.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace fs = std::filesystem;

TEST_CASE("the fuzz target's past findings and seeds pass", "[fuzz]") {
  int replayed = 0;
  for (const char* kind : {"regressions", "corpus"}) {
    const fs::path dir = fs::path(TUMBLE_SOURCE_DIR) / "fuzz" / kind / TUMBLE_FUZZ_TARGET;
    if (!fs::is_directory(dir)) continue;
    for (const auto& entry : fs::directory_iterator(dir)) {
      std::ifstream in(entry.path(), std::ios::binary);
      std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      INFO(entry.path().string());
      CHECK(LLVMFuzzerTestOneInput(bytes.data(), bytes.size()) == 0);
      ++replayed;
    }
  }
  CHECK(replayed > 0);
}
