#include "bench/machine_info.h"

#include <fstream>

namespace tumble::bench {
namespace {

std::string trim(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t");
  const std::size_t b = s.find_last_not_of(" \t");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

}  // namespace

MachineInfo parseCpuinfo(std::istream& cpuinfo) {
  MachineInfo m;
  bool model_seen = false;
  std::string line;
  while (std::getline(cpuinfo, line)) {
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    const std::string key = trim(line.substr(0, colon)), value = trim(line.substr(colon + 1));
    if (key == "processor") ++m.cores;
    else if (key == "model name" && !model_seen && !value.empty()) {
      m.cpu_model = value;
      model_seen = true;
    }
  }
  return m;
}

MachineInfo thisMachine() {
  std::ifstream in("/proc/cpuinfo");
  return in ? parseCpuinfo(in) : MachineInfo{};
}

}  // namespace tumble::bench
