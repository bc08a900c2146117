// tumble: simulate rigid bodies with contact and render them off-screen.
// main parses the command line, runs one subcommand, and maps errors to documented exit codes.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <functional>
#include <map>
#include <string>

#include "app/commands.h"
#include "app/interrupt.h"
#include "base/build_info.h"
#include "base/error.h"

namespace {

const char* kExitCodes = R"(Exit codes:
  0   success
  64  bad command line (unknown flag, malformed value, a --set without PATH=VALUE)
  65  bad scene: malformed JSON, unknown field, wrong type, value out of range, unusable mesh,
      the same in a --set value or a --patch file; or a trajectory from another scene or lacking a
      frame asked for; or video parts that do not join
  66  missing input: the scene, a --patch file, a mesh, a trajectory or a video part does not exist
      or cannot be read
  69  unavailable: no OpenGL (OSMesa) or no H.264 encoder (libx264)
  70  numerical failure during the simulation (NaN or infinite state)
  73  cannot create output: it exists (add -y) or the folder is not writable
  130 interrupted (Ctrl-C); the frames rendered so far are kept, a video is finalised
diff, and render --check-against: 0 frames match, 1 some differ, 2 bad input (missing file, sizes differ)
)";

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"tumble - offline rigid-body animation: a scene file in, frames or a video out", "tumble"};
  app.footer(kExitCodes);
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("tumble ") + tumble::buildVersion() + " (commit " +
                                        tumble::buildCommit() + ")");
  std::map<std::string, std::function<int()>> commands = {
      {"render", tumble::addRenderCommand(app)},
      {"simulate", tumble::addSimulateCommand(app)},
      {"check", tumble::addCheckCommand(app)},
      {"diff", tumble::addDiffCommand(app)},
      {"join", tumble::addJoinCommand(app)},
  };
  // diff has its own exit codes (0/1/2, as diff tools) and footer.
  for (CLI::App* sub : app.get_subcommands({}))
    if (sub->get_footer().empty()) sub->footer(kExitCodes);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? 0 : static_cast<int>(tumble::ExitCode::Usage);
  }
  tumble::installInterruptHandlers();
  try {
    for (CLI::App* sub : app.get_subcommands()) return commands.at(sub->get_name())();
  } catch (const tumble::Error& e) {
    std::fprintf(stderr, "tumble: %s\n", e.what());
    return static_cast<int>(e.code());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tumble: internal error: %s\n", e.what());
    return static_cast<int>(tumble::ExitCode::Software);
  }
  return 0;
}
