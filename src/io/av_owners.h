// Shared by the files that talk to libav directly (video_writer.cpp, video_join.cpp): owners that
// release libav objects on every exit path, and the few choices both make the same way.
#pragma once

#include <string>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

namespace tumble::av {

inline std::string errorText(int err) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(err, text, sizeof text);
  return text;
}

// An output context, with its file closed if it opened one.
struct OutputFree {
  void operator()(AVFormatContext* f) const {
    if (f->pb && !(f->oformat->flags & AVFMT_NOFILE)) avio_closep(&f->pb);
    avformat_free_context(f);
  }
};
struct InputFree {
  void operator()(AVFormatContext* f) const { avformat_close_input(&f); }
};
struct PacketFree {
  void operator()(AVPacket* p) const { av_packet_free(&p); }
};

// faststart: the index (moov) goes before the data, so browsers play while downloading.
inline bool wantsFaststart(const AVOutputFormat* format) {
  std::string name = format->name;   // "mov,mp4,m4a,3gp,3g2,mj2" for the demuxer; muxers are single
  return name == "mp4" || name == "mov";
}

}  // namespace tumble::av
