#include "io/video_sink.h"

#include <string>
#include <system_error>

#include "base/error.h"

#include "io/atomic_file.h"

namespace tumble {

namespace fs = std::filesystem;

namespace {

// The encoder names the file it writes, the hidden temporary one; the user knows the final name.
template <typename F>
void namingFinal(const fs::path& temp, const fs::path& final_path, F&& work) {
  try {
    work();
  } catch (const Error& e) {
    std::string message = e.what();
    for (std::size_t at; (at = message.find(temp.string())) != std::string::npos;)
      message.replace(at, temp.string().size(), final_path.string());
    throw Error(e.code(), message);
  }
}

}  // namespace

VideoSink::VideoSink(const OutputTarget& target, const VideoSettings& settings, bool overwrite)
    : final_(target.path), overwrite_(overwrite) {
  std::error_code ec;
  if (!overwrite_ && fs::exists(final_, ec)) {
    throwCantWrite(final_, "it already exists (use -y/--overwrite to replace it)");
  }
  fs::path folder = final_.parent_path();
  if (!folder.empty()) fs::create_directories(folder, ec);
  if (ec) throwCantWrite(folder, ec.message());
  // The real extension stays last so libavformat picks the same container as for the final name.
  temp_ = temporarySibling(final_, "partial", /*keep_extension*/ true);
  try {
    namingFinal(temp_, final_, [&] { writer_ = std::make_unique<VideoWriter>(temp_, settings); });
  } catch (...) {
    fs::remove(temp_, ec);   // the encoder may have created the file before failing
    throw;
  }
}

VideoSink::~VideoSink() {
  if (done_) return;
  try {
    finishPartial();
  } catch (...) {
    // A destructor must not throw; finishPartial has already removed what it could not finish.
  }
}

void VideoSink::write(const RgbImage& image, int /*frame_number*/) {
  namingFinal(temp_, final_, [&] { writer_->write(image); });
}

void VideoSink::finish() {
  if (done_) return;
  done_ = true;
  try {
    namingFinal(temp_, final_, [&] { writer_->finish(); });
  } catch (...) {
    std::error_code ignored;
    fs::remove(temp_, ignored);
    throw;
  }
  writer_.reset();
  commitFile(temp_, final_, overwrite_);
}

fs::path VideoSink::partialPath(const fs::path& final_path) {
  return final_path.parent_path() /
         (final_path.stem().string() + ".partial" + final_path.extension().string());
}

fs::path VideoSink::finishPartial() {
  if (done_) return {};
  done_ = true;
  std::error_code ignored;
  if (writer_->framesWritten() == 0) {
    writer_.reset();
    fs::remove(temp_, ignored);
    return {};
  }
  try {
    writer_->finish();
  } catch (...) {
    writer_.reset();
    fs::remove(temp_, ignored);
    throw;
  }
  writer_.reset();
  fs::path partial = partialPath(final_);
  commitFile(temp_, partial, /*overwrite*/ true);   // a stale partial is worth nothing
  return partial;
}

std::string VideoSink::describe() const { return final_.string(); }

}  // namespace tumble
