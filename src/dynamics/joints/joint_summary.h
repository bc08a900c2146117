// A joint count for `tumble check`'s stage lines: "3 joints (2 hinge, 1 ball)".
#pragma once

#include <string>

#include "dynamics/world.h"

namespace tumble {

std::string describeJoints(const World& world);

}  // namespace tumble
