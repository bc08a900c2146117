// Meshes come from anywhere: every model of Debian's assimp-testmodels package (hundreds of files,
// many deliberately odd) is imported as a body. Each must either load into valid convex pieces or
// be refused with a tumble::Error that names the file — never crash, hang or throw anything else.
// Each file is imported in a child process, so a crash or a hang is caught and named instead of
// taking the test down, with a time limit per file (alarm) against hangs.
#include <catch2/catch.hpp>

#include <assimp/Importer.hpp>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "base/error.h"
#include "geometry/mesh_import.h"
#include "piece_validity.h"

using namespace tumble;
namespace fs = std::filesystem;

namespace {

const fs::path kModels = "/usr/share/assimp/models";
// s of CPU time: far above any model's import time here (the slowest takes about a second in
// Release), so only a hang reaches it; sanitizer builds run several times slower. CPU time, not
// wall time, so that a loaded machine (ctest -j, other builds) cannot make a slow file look hung;
// the wall-clock alarm at ten times the limit only catches a child blocked without using CPU.
#ifdef TUMBLE_SANITIZED
// Under ASan + UBSan AC/sample_subdiv.ac took 313 s of CPU at def6d4b (2026-11-24), and a 300 s
// limit called it hung: not assimp's import (5 s) but the convexity check of its one hull
// (piece_validity.h), 82 038 vertices against 137 192 faces. Such hulls are cut to 255 vertices
// (geometry/hull_simplify.h, 0d9bcb9), and the file takes about 2 s in Release.
constexpr unsigned kTimeLimit = 900;
#else
constexpr unsigned kTimeLimit = 60;
#endif

// Child exit codes besides tumble's own (65, 66): how an import went wrong.
constexpr int kInvalidPiece = 3, kOtherException = 4;

struct Outcome {
  int status = 0;        // as waitpid reports it
  std::string message;   // what the child said
};

// Imports `file` in a child and reports how it ended.
Outcome importInChild(const fs::path& file) {
  int pipe_fd[2];
  REQUIRE(::pipe(pipe_fd) == 0);
  std::fflush(nullptr);
  pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    ::close(pipe_fd[0]);
    rlimit cpu{kTimeLimit, kTimeLimit + 1};
    ::setrlimit(RLIMIT_CPU, &cpu);
    ::alarm(10 * kTimeLimit);
    int code = 0;
    std::string said;
    try {
      ImportedPieces in = importConvexPieces(file);
      for (const ConvexPiece& p : in.pieces)
        if (std::string problem = test::convexPieceProblem(p); !problem.empty()) {
          said = "piece '" + p.name + "': " + problem;
          code = kInvalidPiece;
          break;
        }
      if (code == 0) said = std::to_string(in.pieces.size()) + " pieces";
    } catch (const Error& e) {
      said = e.what();
      code = static_cast<int>(e.code());
    } catch (const std::exception& e) {
      said = std::string("escaped exception: ") + e.what();
      code = kOtherException;
    }
    (void)!::write(pipe_fd[1], said.data(), said.size());
    ::_exit(code);   // no destructors or atexit handlers of the parent's state in the child
  }
  ::close(pipe_fd[1]);
  Outcome out;
  char buffer[4096];
  for (ssize_t n; (n = ::read(pipe_fd[0], buffer, sizeof buffer)) > 0;) out.message.append(buffer, size_t(n));
  ::close(pipe_fd[0]);
  ::waitpid(pid, &out.status, 0);
  return out;
}

// Files assimp claims by their extension; textures, buffers and read-mes in the package are not.
std::vector<fs::path> modelFiles() {
  Assimp::Importer importer;
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(kModels))
    if (entry.is_regular_file() && importer.IsExtensionSupported(entry.path().extension().string()))
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("every assimp test model loads as convex pieces or is refused with a clear error",
          "[import][assimp-models]") {
  if (!fs::is_directory(kModels)) {
    WARN("skipped: " << kModels << " is absent; apt-get install assimp-testmodels to run this test");
    return;
  }
  const std::vector<fs::path> files = modelFiles();
  REQUIRE(files.size() > 100);
  int loaded = 0, refused = 0, broke = 0;
  std::ofstream report(fs::path(TUMBLE_BINARY_DIR) / "assimp_models_report.txt");
  for (const fs::path& file : files) {
    Outcome out = importInChild(file);
    std::string verdict;
    if (WIFSIGNALED(out.status)) {
      int sig = WTERMSIG(out.status);
      verdict = sig == SIGXCPU || sig == SIGALRM ? "HANG (over " + std::to_string(kTimeLimit) + " s)"
                               : "CRASH (signal " + std::to_string(sig) + ")";
    } else if (int code = WEXITSTATUS(out.status); code == 0) {
      verdict = "loaded";
      ++loaded;
    } else if (code == int(ExitCode::BadInput) || code == int(ExitCode::MissingInput)) {
      // A clear refusal names the file it refuses.
      verdict = out.message.find(file.string()) != std::string::npos ? "refused" : "UNCLEAR";
      refused += verdict == "refused";
    } else {
      verdict = "BROKE (exit " + std::to_string(code) + ")";
    }
    if (verdict != "loaded" && verdict != "refused") ++broke;
    report << verdict << "\t" << file.string() << "\t" << out.message << "\n";
    INFO(file.string() << ": " << out.message);
    CHECK((verdict == "loaded" || verdict == "refused"));
  }
  std::printf("assimp test models: %zu tried, %d loaded, %d refused, %d broke (report: %s)\n",
              files.size(), loaded, refused, broke,
              (fs::path(TUMBLE_BINARY_DIR) / "assimp_models_report.txt").c_str());
}
