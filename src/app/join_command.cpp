// tumble join OUTPUT PARTS... : a video rendered in chunks (render --shard) back into one file,
// without re-encoding.
#include <chrono>
#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "io/video_join.h"
#include "io/video_writer.h"

namespace tumble {
namespace {

struct JoinOptions {
  std::string output;
  std::vector<std::string> parts;
  bool overwrite = false, quiet = false;
};

int run(const JoinOptions& o) {
  setVideoLogVerbose(false);   // libav's notes (the faststart pass) would clutter the summary
  auto start = std::chrono::steady_clock::now();
  std::vector<std::filesystem::path> parts(o.parts.begin(), o.parts.end());
  JoinSummary joined = joinVideoParts(o.output, parts, o.overwrite);
  double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!o.quiet)
    std::fprintf(stderr, "tumble: joined %d parts (%ld frames) into %s without re-encoding in %.2f s\n", joined.parts,
                 joined.frames, o.output.c_str(), wall);
  return 0;
}

}  // namespace

std::function<int()> addJoinCommand(CLI::App& app) {
  auto o = std::make_shared<JoinOptions>();
  CLI::App* cmd = app.add_subcommand(
      "join", "Join a video rendered in chunks (NAME.part-0001-of-0004.mp4 ...) into one, copying the stream: no "
              "re-encoding; every part must be there once, all encoded alike");
  cmd->add_option("output", o->output, "The joined video, e.g. out/clip.mp4")->required();
  cmd->add_option("parts", o->parts, "The parts, in any order, e.g. out/clip.part-*.mp4")->required();
  cmd->add_flag("-y,--overwrite", o->overwrite, "Replace an existing output");
  cmd->add_flag("-q,--quiet", o->quiet, "Print nothing but errors");
  return [o] { return run(*o); };
}

}  // namespace tumble
