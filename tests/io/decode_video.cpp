#include "decode_video.h"

#include <algorithm>
#include <fstream>
#include <memory>
#include <stdexcept>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}

namespace tumble::test {

namespace {

struct Input {
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVFrame* frame = av_frame_alloc();
  AVPacket* packet = av_packet_alloc();
  SwsContext* sws = nullptr;
  int stream = -1;
  ~Input() {
    sws_freeContext(sws);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&codec);
    avformat_close_input(&format);
  }
};

void check(int err, const std::string& what) {
  if (err >= 0) return;
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(err, text, sizeof text);
  throw std::runtime_error(what + ": " + text);
}

std::string orEmpty(const char* s) { return s ? s : ""; }

void open(Input& in, const std::filesystem::path& path, DecodedVideo& out) {
  check(avformat_open_input(&in.format, path.c_str(), nullptr, nullptr), "open " + path.string());
  check(avformat_find_stream_info(in.format, nullptr), "stream info");
  const AVCodec* decoder = nullptr;
  in.stream = av_find_best_stream(in.format, AVMEDIA_TYPE_VIDEO, -1, -1, &decoder, 0);
  check(in.stream, "no video stream");
  AVStream* s = in.format->streams[in.stream];
  in.codec = avcodec_alloc_context3(decoder);
  check(avcodec_parameters_to_context(in.codec, s->codecpar), "codec parameters");
  in.codec->thread_count = 1;
  check(avcodec_open2(in.codec, decoder, nullptr), "open decoder");
  const AVCodecParameters* p = s->codecpar;
  out.width = p->width;
  out.height = p->height;
  out.fps = av_q2d(s->avg_frame_rate);
  out.duration = s->duration != AV_NOPTS_VALUE
                     ? s->duration * av_q2d(s->time_base)
                     : static_cast<double>(in.format->duration) / AV_TIME_BASE;
  out.codec = avcodec_get_name(p->codec_id);
  out.pix_fmt = orEmpty(av_get_pix_fmt_name(static_cast<AVPixelFormat>(p->format)));
  out.color_primaries = orEmpty(av_color_primaries_name(p->color_primaries));
  out.color_space = orEmpty(av_color_space_name(p->color_space));
  out.color_range = orEmpty(av_color_range_name(p->color_range));
}

// Converts the decoded frame to RGB with the matrix and range it is tagged with.
void keepFrame(Input& in, DecodedVideo& out) {
  AVFrame* f = in.frame;
  in.sws = sws_getCachedContext(in.sws, f->width, f->height, static_cast<AVPixelFormat>(f->format),
                                f->width, f->height, AV_PIX_FMT_RGB24,
                                SWS_BILINEAR | SWS_ACCURATE_RND, nullptr, nullptr, nullptr);
  int space = f->colorspace == AVCOL_SPC_BT709 ? SWS_CS_ITU709 : SWS_CS_ITU601;
  const int* table = sws_getCoefficients(space);
  sws_setColorspaceDetails(in.sws, table, f->color_range == AVCOL_RANGE_JPEG, table, 1, 0,
                           1 << 16, 1 << 16);
  RgbImage image;
  image.width = f->width;
  image.height = f->height;
  image.pixels.resize(static_cast<std::size_t>(f->width) * f->height * 3);
  std::uint8_t* dst[1] = {image.pixels.data()};
  int dst_stride[1] = {f->width * 3};
  sws_scale(in.sws, f->data, f->linesize, 0, f->height, dst, dst_stride);
  out.frames.push_back(std::move(image));
  std::vector<std::uint8_t> y(static_cast<std::size_t>(f->width) * f->height);
  for (int row = 0; row < f->height; ++row) {
    std::copy_n(f->data[0] + row * f->linesize[0], f->width, y.data() + row * f->width);
  }
  out.luma.push_back(std::move(y));
}

void receiveAll(Input& in, DecodedVideo& out) {
  for (;;) {
    int err = avcodec_receive_frame(in.codec, in.frame);
    if (err == AVERROR(EAGAIN) || err == AVERROR_EOF) return;
    check(err, "decode");
    keepFrame(in, out);
    av_frame_unref(in.frame);
  }
}

}  // namespace

DecodedVideo decodeVideo(const std::filesystem::path& path) {
  Input in;
  DecodedVideo out;
  open(in, path, out);
  while (av_read_frame(in.format, in.packet) >= 0) {
    if (in.packet->stream_index == in.stream) {
      check(avcodec_send_packet(in.codec, in.packet), "decode");
      receiveAll(in, out);
    }
    av_packet_unref(in.packet);
  }
  check(avcodec_send_packet(in.codec, nullptr), "flush");
  receiveAll(in, out);
  return out;
}

std::vector<std::string> topLevelBoxes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::string> boxes;
  const auto file_size = static_cast<std::uint64_t>(std::filesystem::file_size(path));
  std::uint64_t pos = 0;
  while (pos + 8 <= file_size) {
    unsigned char head[16];
    in.seekg(static_cast<std::streamoff>(pos));
    in.read(reinterpret_cast<char*>(head), 8);
    std::uint64_t size = 0;
    for (int i = 0; i < 4; ++i) size = (size << 8) | head[i];
    boxes.emplace_back(reinterpret_cast<char*>(head + 4), 4);
    if (size == 1) {   // a 64-bit size follows the type
      in.read(reinterpret_cast<char*>(head + 8), 8);
      size = 0;
      for (int i = 8; i < 16; ++i) size = (size << 8) | head[i];
    } else if (size == 0) {   // the box runs to the end of the file
      size = file_size - pos;
    }
    if (size < 8) break;   // malformed; stop rather than loop
    pos += size;
  }
  return boxes;
}

}  // namespace tumble::test
