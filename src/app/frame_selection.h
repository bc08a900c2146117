// Which frames a command works on: 1..N by default, narrowed by -s/--start and -e/--end
// (Blender's spelling), or listed with --frames "1,5,10..20" (ranges inclusive).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace tumble {

// Ascending, without duplicates. Throws Error(Usage) for malformed lists or frames outside 1..total.
std::vector<int> selectFrames(int total, std::optional<int> start, std::optional<int> end,
                              const std::string& list);

}  // namespace tumble
