#include "geometry/mesh_import_checks.h"

#include <cctype>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>

#include "base/error.h"

namespace tumble {
namespace {

// assimp 5.2 never returns from a PLY file whose header lacks its `end_header` line (a file cut
// short while being written or copied: seen in our tests), so such a file is refused before
// assimp sees it. A header longer than 1 MB is not a mesh we want either.
void refuseTruncatedPly(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line.substr(0, 3) != "ply") return;
  std::streamoff read = 0;
  while (std::getline(in, line) && read < (1 << 20)) {
    if (line.rfind("end_header", 0) == 0) return;
    read += std::streamoff(line.size()) + 1;
  }
  throw Error(ExitCode::BadInput,
              file.string() + ": the PLY header never ends (no end_header line); is the file "
                              "truncated?");
}

// assimp-testmodels' invalid/OutOfMemory.off declares 353535235358 vertices in a 309-byte file:
// assimp 5.2 then spends minutes (and memory) before giving up. Every vertex takes at least two
// bytes of text ("0\n" per coordinate is six), every face at least two, so counts above the file
// size are impossible and the file is refused at once.
void refuseImpossibleOff(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string word;
  if (!(in >> word) || word.size() < 3 || word.substr(word.size() - 3) != "OFF") return;
  // The counts follow the keyword, on its line or after blank and comment lines.
  std::string line;
  std::getline(in, line);
  for (int lines = 0; line.substr(0, line.find('#')).find_first_not_of(" \t\r") == std::string::npos; ++lines)
    if (lines == 64 || !std::getline(in, line)) return;
  std::istringstream counts(line.substr(0, line.find('#')));
  double vertices = 0, faces = 0;
  if (!(counts >> vertices >> faces)) return;   // malformed: assimp's own error says so
  const double bytes = double(std::filesystem::file_size(file));
  if (vertices <= bytes && faces <= bytes) return;
  std::ostringstream msg;
  msg << file.string() << ": the OFF header declares " << std::fixed << std::setprecision(0) << vertices
      << " vertices and " << faces << " faces, more than a " << bytes << "-byte file can hold";
  throw Error(ExitCode::BadInput, msg.str());
}

}  // namespace

void refuseFilesAssimpHangsOn(const std::filesystem::path& file) {
  refuseTruncatedPly(file);
  refuseImpossibleOff(file);
}

}  // namespace tumble
