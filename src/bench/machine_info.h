// The machine a run was measured on, for the head of the results page: the figures are wall
// times, meaningless without the CPU and the number of cores beside them.
#pragma once

#include <istream>
#include <string>

namespace tumble::bench {

struct MachineInfo {
  std::string cpu_model = "unknown CPU";   // /proc/cpuinfo's first "model name"
  int cores = 0;                           // logical processors listed there
};

MachineInfo parseCpuinfo(std::istream& cpuinfo);
// This machine's /proc/cpuinfo; the defaults where it cannot be read.
MachineInfo thisMachine();

}  // namespace tumble::bench
