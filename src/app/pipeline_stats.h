// -v: where the simulation's time went, stage by stage, and what the contact pipeline did.
#pragma once

#include "dynamics/pipeline.h"

namespace tumble {

void printPipelineStats(const Pipeline& pipeline);

}  // namespace tumble
