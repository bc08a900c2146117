#include "io/video_writer.h"

#include <atomic>
#include <cstring>
#include <string>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include "base/error.h"
#include "io/atomic_file.h"
#include "io/av_owners.h"

namespace tumble {

namespace fs = std::filesystem;

namespace {

using FormatFree = av::OutputFree;
using PacketFree = av::PacketFree;

std::string avError(int err) { return av::errorText(err); }

// Owners for the libav objects, so every exit path (including exceptions) releases them.
struct CodecFree {
  void operator()(AVCodecContext* c) const { avcodec_free_context(&c); }
};
struct FrameFree {
  void operator()(AVFrame* f) const { av_frame_free(&f); }
};
struct SwsFree {
  void operator()(SwsContext* s) const { sws_freeContext(s); }
};

std::atomic<bool> log_level_chosen{false};

using av::wantsFaststart;

}  // namespace

void setVideoLogVerbose(bool verbose) {
  log_level_chosen = true;
  av_log_set_level(verbose ? AV_LOG_INFO : AV_LOG_WARNING);
}

struct VideoWriter::Impl {
  fs::path path;
  VideoSettings settings;
  std::unique_ptr<AVFormatContext, FormatFree> format;
  std::unique_ptr<AVCodecContext, CodecFree> codec;
  std::unique_ptr<AVFrame, FrameFree> frame;
  std::unique_ptr<AVPacket, PacketFree> packet;
  std::unique_ptr<SwsContext, SwsFree> sws;
  AVStream* stream = nullptr;   // owned by `format`
  int frames = 0;
  bool finished = false;

  void openContainer();
  void openEncoder(const AVCodec* encoder);
  void openFile();
  void makeConverter();
  void drain();   // moves every packet the encoder has ready into the file
  [[noreturn]] void fail(const std::string& what, int err) const {
    throwCantWrite(path, what + ": " + avError(err));
  }
};

void VideoWriter::Impl::openContainer() {
  AVFormatContext* raw = nullptr;
  avformat_alloc_output_context2(&raw, nullptr, nullptr, path.c_str());
  if (!raw) {
    throw Error(ExitCode::Usage, "cannot tell the video container from " + path.string() +
                                     ": use .mp4, .mkv or .mov");
  }
  format.reset(raw);
}

void VideoWriter::Impl::openEncoder(const AVCodec* encoder) {
  codec.reset(avcodec_alloc_context3(encoder));
  AVCodecContext* c = codec.get();
  c->width = settings.width;
  c->height = settings.height;
  c->pix_fmt = AV_PIX_FMT_YUV420P;
  c->sample_aspect_ratio = AVRational{1, 1};
  // pts counts frames, so the time base is one frame; the muxer may pick a finer one.
  c->time_base = AVRational{1, settings.fps};
  c->framerate = AVRational{settings.fps, 1};
  c->gop_size = 2 * settings.fps;   // a key frame every 2 s: cheap seeking, little size cost
  // Rendered frames are sRGB-ish computer graphics; HD players assume BT.709, so tag it and
  // convert with the same matrix (makeConverter) or colours shift (greens most).
  c->color_primaries = AVCOL_PRI_BT709;
  c->color_trc = AVCOL_TRC_BT709;
  c->colorspace = AVCOL_SPC_BT709;
  c->color_range = AVCOL_RANGE_MPEG;
  c->thread_count = settings.threads;
  if (format->oformat->flags & AVFMT_GLOBALHEADER) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  av_opt_set(c->priv_data, "preset", settings.preset.c_str(), 0);
  av_opt_set(c->priv_data, "crf", std::to_string(settings.crf).c_str(), 0);
  if (int err = avcodec_open2(c, encoder, nullptr); err < 0) {
    throw Error(ExitCode::Unavailable, "cannot open the libx264 encoder for " + path.string() +
                                           ": " + avError(err));
  }
  stream = avformat_new_stream(format.get(), nullptr);
  if (!stream) fail("cannot add a video stream", AVERROR(ENOMEM));
  stream->time_base = c->time_base;
  stream->avg_frame_rate = c->framerate;
  if (int err = avcodec_parameters_from_context(stream->codecpar, c); err < 0) {
    fail("cannot set stream parameters", err);
  }
}

void VideoWriter::Impl::openFile() {
  if (!(format->oformat->flags & AVFMT_NOFILE)) {
    if (int err = avio_open(&format->pb, path.c_str(), AVIO_FLAG_WRITE); err < 0) {
      throwCantWrite(path, avError(err));
    }
  }
  AVDictionary* options = nullptr;
  // faststart: the index (moov) goes before the data, so browsers play while downloading.
  // use_metadata_tags: MP4 keeps the metadata's own keys (tumble_scene_hash), not only iTunes'.
  if (wantsFaststart(format->oformat)) av_dict_set(&options, "movflags", "+faststart+use_metadata_tags", 0);
  for (const auto& [key, value] : settings.metadata) av_dict_set(&format->metadata, key.c_str(), value.c_str(), 0);
  int err = avformat_write_header(format.get(), &options);
  av_dict_free(&options);
  if (err < 0) fail("cannot write the container header", err);
}

void VideoWriter::Impl::makeConverter() {
  int w = settings.width, h = settings.height;
  sws.reset(sws_getContext(w, h, AV_PIX_FMT_RGB24, w, h, AV_PIX_FMT_YUV420P,
                           SWS_BILINEAR | SWS_ACCURATE_RND, nullptr, nullptr, nullptr));
  if (!sws) fail("cannot create the colour converter", AVERROR(EINVAL));
  // swscale converts with BT.601 unless told; the stream is tagged BT.709, limited range.
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(sws.get(), bt709, /*srcRange full*/ 1, bt709, /*dstRange mpeg*/ 0,
                           0, 1 << 16, 1 << 16);
  frame.reset(av_frame_alloc());
  packet.reset(av_packet_alloc());
  if (!frame || !packet) fail("cannot allocate a frame", AVERROR(ENOMEM));
  frame->format = AV_PIX_FMT_YUV420P;
  frame->width = w;
  frame->height = h;
  frame->color_primaries = AVCOL_PRI_BT709;
  frame->color_trc = AVCOL_TRC_BT709;
  frame->colorspace = AVCOL_SPC_BT709;
  frame->color_range = AVCOL_RANGE_MPEG;
  if (int err = av_frame_get_buffer(frame.get(), 0); err < 0) fail("cannot allocate a frame", err);
}

void VideoWriter::Impl::drain() {
  for (;;) {
    int err = avcodec_receive_packet(codec.get(), packet.get());
    if (err == AVERROR(EAGAIN) || err == AVERROR_EOF) return;
    if (err < 0) fail("encoding failed", err);
    // libx264 leaves duration unset; without it the last frame has no length and the file is
    // one frame short.
    if (packet->duration == 0) packet->duration = 1;
    // Codec time base (1/fps) to the stream's, which the muxer chose in avformat_write_header.
    av_packet_rescale_ts(packet.get(), codec->time_base, stream->time_base);
    packet->stream_index = stream->index;
    err = av_interleaved_write_frame(format.get(), packet.get());   // takes the packet's data
    if (err < 0) fail("cannot write a packet", err);
  }
}

VideoWriter::VideoWriter(const fs::path& path, const VideoSettings& settings)
    : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  impl_->settings = settings;
  if (settings.width <= 0 || settings.height <= 0 || settings.width % 2 || settings.height % 2) {
    throw Error(ExitCode::BadInput, "cannot write " + path.string() + ": " +
                                        std::to_string(settings.width) + "x" +
                                        std::to_string(settings.height) +
                                        " is not possible, yuv420p needs even sizes; use --size "
                                        "1280x720");
  }
  if (settings.fps <= 0) throw Error(ExitCode::BadInput, "frame rate must be positive");
  if (!log_level_chosen.exchange(true)) av_log_set_level(AV_LOG_WARNING);
  const AVCodec* encoder = avcodec_find_encoder_by_name("libx264");
  if (!encoder) {
    throw Error(ExitCode::Unavailable,
                "no H.264 encoder: this libavcodec was built without libx264; install "
                "libavcodec59 with libx264 (apt-get install libavcodec-extra or ffmpeg)");
  }
  impl_->openContainer();
  impl_->openEncoder(encoder);
  impl_->makeConverter();
  impl_->openFile();
}

VideoWriter::~VideoWriter() = default;

void VideoWriter::write(const RgbImage& image) {
  Impl& m = *impl_;
  if (m.finished) throwCantWrite(m.path, "frame written after finish()");
  if (image.width != m.settings.width || image.height != m.settings.height ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
    throwCantWrite(m.path, "frame is " + std::to_string(image.width) + "x" +
                               std::to_string(image.height) + ", the video is " +
                               std::to_string(m.settings.width) + "x" +
                               std::to_string(m.settings.height));
  }
  // The encoder may still hold a reference to the previous frame's buffers.
  if (int err = av_frame_make_writable(m.frame.get()); err < 0) m.fail("cannot write a frame", err);
  const std::uint8_t* src[1] = {image.pixels.data()};
  const int src_stride[1] = {image.width * 3};
  sws_scale(m.sws.get(), src, src_stride, 0, image.height, m.frame->data, m.frame->linesize);
  m.frame->pts = m.frames;
  if (int err = avcodec_send_frame(m.codec.get(), m.frame.get()); err < 0) {
    m.fail("encoding failed", err);
  }
  ++m.frames;
  m.drain();
}

void VideoWriter::finish() {
  Impl& m = *impl_;
  if (m.finished) return;
  m.finished = true;   // even if flushing fails, a second finish() must not retry
  if (int err = avcodec_send_frame(m.codec.get(), nullptr); err < 0) m.fail("encoding failed", err);
  m.drain();
  if (int err = av_write_trailer(m.format.get()); err < 0) m.fail("cannot finish the file", err);
  if (int err = avio_closep(&m.format->pb); err < 0) m.fail("cannot close the file", err);
}

int VideoWriter::framesWritten() const { return impl_->frames; }

}  // namespace tumble
