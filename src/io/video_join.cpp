#include "io/video_join.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include "base/error.h"
#include "io/atomic_file.h"
#include "io/av_owners.h"

namespace tumble {

namespace fs = std::filesystem;

namespace {

using Input = std::unique_ptr<AVFormatContext, av::InputFree>;
using Output = std::unique_ptr<AVFormatContext, av::OutputFree>;
using Packet = std::unique_ptr<AVPacket, av::PacketFree>;

[[noreturn]] void bad(const fs::path& file, const std::string& why) {
  throw Error(ExitCode::BadInput, "cannot join " + file.string() + ": " + why);
}

std::optional<int> number(const std::string& text) {
  int value = 0;
  auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
  return value;
}

struct OpenPart {
  fs::path path;
  Input input;
  AVStream* stream = nullptr;   // its one video stream, owned by `input`
};

OpenPart openPart(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw Error(ExitCode::MissingInput, "cannot read " + path.string());
  AVFormatContext* raw = nullptr;
  if (int err = avformat_open_input(&raw, path.c_str(), nullptr, nullptr); err < 0)
    bad(path, "not a video libavformat can read (" + av::errorText(err) + ")");
  OpenPart part{path, Input(raw)};
  if (int err = avformat_find_stream_info(raw, nullptr); err < 0) bad(path, av::errorText(err));
  for (unsigned i = 0; i < raw->nb_streams; ++i) {
    if (raw->streams[i]->codecpar->codec_type != AVMEDIA_TYPE_VIDEO) continue;
    if (part.stream) bad(path, "it holds more than one video stream");
    part.stream = raw->streams[i];
  }
  if (!part.stream) bad(path, "it holds no video stream");
  return part;
}

// A copied stream decodes as one only if every part was encoded alike: same codec and headers
// (SPS/PPS), size, pixel format, frame rate and time base.
void checkCompatible(const OpenPart& first, const OpenPart& part) {
  const AVCodecParameters* a = first.stream->codecpar;
  const AVCodecParameters* b = part.stream->codecpar;
  auto differs = [&](const std::string& what, const std::string& x, const std::string& y) {
    bad(part.path, "its " + what + " (" + y + ") differs from " + first.path.string() + "'s (" + x + ")");
  };
  if (a->codec_id != b->codec_id) differs("codec", avcodec_get_name(a->codec_id), avcodec_get_name(b->codec_id));
  if (a->width != b->width || a->height != b->height)
    differs("size", std::to_string(a->width) + "x" + std::to_string(a->height),
            std::to_string(b->width) + "x" + std::to_string(b->height));
  if (a->format != b->format) differs("pixel format", std::to_string(a->format), std::to_string(b->format));
  AVRational ra = first.stream->avg_frame_rate, rb = part.stream->avg_frame_rate;
  if (av_cmp_q(ra, rb) != 0)
    differs("frame rate", std::to_string(ra.num) + "/" + std::to_string(ra.den),
            std::to_string(rb.num) + "/" + std::to_string(rb.den));
  AVRational ta = first.stream->time_base, tb = part.stream->time_base;
  if (av_cmp_q(ta, tb) != 0)
    differs("time base", std::to_string(ta.num) + "/" + std::to_string(ta.den),
            std::to_string(tb.num) + "/" + std::to_string(tb.den));
  if (a->extradata_size != b->extradata_size ||
      (a->extradata_size > 0 && std::memcmp(a->extradata, b->extradata, a->extradata_size) != 0))
    bad(part.path, "its codec headers differ from " + first.path.string() + "'s (encoded with other settings)");
}

// The parts in order 1..N, each once, all of one video; refuses anything else.
std::vector<fs::path> orderedParts(const std::vector<fs::path>& parts) {
  if (parts.empty()) throw Error(ExitCode::Usage, "join: no parts given");
  std::optional<VideoPartName> first = parseVideoPartName(parts.front());
  std::vector<fs::path> ordered;
  for (const fs::path& p : parts) {
    std::optional<VideoPartName> name = parseVideoPartName(p);
    if (!name) bad(p, "its name is not NAME.part-I-of-N.EXT (as render --shard writes)");
    if (name->count != first->count || name->video.filename() != first->video.filename())
      bad(p, "it is part of " + name->video.filename().string() + " in " + std::to_string(name->count) +
                 " parts, " + parts.front().string() + " of " + first->video.filename().string() + " in " +
                 std::to_string(first->count));
    if (ordered.empty()) ordered.resize(static_cast<std::size_t>(first->count));
    fs::path& slot = ordered[static_cast<std::size_t>(name->index - 1)];
    if (!slot.empty()) bad(p, "part " + std::to_string(name->index) + " is given twice (also " + slot.string() + ")");
    slot = p;
  }
  for (std::size_t i = 0; i < ordered.size(); ++i)
    if (ordered[i].empty())
      throw Error(ExitCode::BadInput,
                  "cannot join: part " + std::to_string(i + 1) + " of " + std::to_string(ordered.size()) + " (" +
                      videoPartPath(parts.front().parent_path() / first->video.filename(), static_cast<int>(i + 1),
                                    first->count).string() + ") is missing");
  return ordered;
}

// Copies every part's packets into `temp`, timestamps shifted; `output` names it in messages.
JoinSummary writeJoined(const fs::path& temp, const fs::path& output, std::vector<OpenPart>& opened) {
  AVFormatContext* raw = nullptr;
  avformat_alloc_output_context2(&raw, nullptr, nullptr, temp.c_str());
  if (!raw) throw Error(ExitCode::Usage, "cannot tell the video container from " + output.string() + ": use .mp4, .mkv or .mov");
  Output out(raw);
  auto fail = [&](const std::string& what, int err) { throwCantWrite(output, what + ": " + av::errorText(err)); };
  const AVStream* in0 = opened.front().stream;
  AVStream* stream = avformat_new_stream(raw, nullptr);
  if (!stream) fail("cannot add a stream", AVERROR(ENOMEM));
  if (int err = avcodec_parameters_copy(stream->codecpar, in0->codecpar); err < 0) fail("cannot copy the stream", err);
  stream->codecpar->codec_tag = 0;   // let the output container pick its own tag
  stream->time_base = in0->time_base;
  stream->avg_frame_rate = in0->avg_frame_rate;
  if (int err = avio_open(&raw->pb, temp.c_str(), AVIO_FLAG_WRITE); err < 0) fail("cannot create it", err);
  AVDictionary* options = nullptr;
  if (av::wantsFaststart(raw->oformat)) av_dict_set(&options, "movflags", "+faststart", 0);
  int err = avformat_write_header(raw, &options);
  av_dict_free(&options);
  if (err < 0) fail("cannot write the container header", err);

  // Each part starts at time 0; shift it to start where the previous one ended (in the parts'
  // shared time base), as the concat demuxer does.
  const AVRational tb = in0->time_base;
  const std::int64_t frame = av_rescale_q(1, av_inv_q(in0->avg_frame_rate), tb);
  std::int64_t offset = 0;   // where the part being copied starts in the joined video
  JoinSummary summary{static_cast<int>(opened.size()), 0};
  Packet packet(av_packet_alloc());
  for (OpenPart& part : opened) {
    const std::int64_t start = part.stream->start_time != AV_NOPTS_VALUE ? part.stream->start_time : 0;
    std::int64_t end = 0;   // the part's length
    while ((err = av_read_frame(part.input.get(), packet.get())) >= 0) {
      if (packet->stream_index != part.stream->index) {
        av_packet_unref(packet.get());
        continue;
      }
      if (packet->pts == AV_NOPTS_VALUE) bad(part.path, "a packet without a timestamp");
      end = std::max(end, packet->pts - start + (packet->duration > 0 ? packet->duration : frame));
      packet->pts += offset - start;
      if (packet->dts != AV_NOPTS_VALUE) packet->dts += offset - start;
      av_packet_rescale_ts(packet.get(), tb, stream->time_base);
      packet->stream_index = stream->index;
      packet->pos = -1;
      ++summary.frames;
      if ((err = av_interleaved_write_frame(raw, packet.get())) < 0) fail("cannot write a packet", err);
    }
    if (err != AVERROR_EOF) bad(part.path, "cannot read it to the end (" + av::errorText(err) + ")");
    offset += end;
  }
  if ((err = av_write_trailer(raw)) < 0) fail("cannot finish the file", err);
  if ((err = avio_closep(&raw->pb)) < 0) fail("cannot close the file", err);
  return summary;
}

}  // namespace

fs::path videoPartPath(const fs::path& video, int index, int count) {
  char tag[64];
  std::snprintf(tag, sizeof tag, ".part-%04d-of-%04d", index, count);
  fs::path part = video;
  part.replace_filename(video.stem().string() + tag + video.extension().string());
  return part;
}

std::optional<VideoPartName> parseVideoPartName(const fs::path& part) {
  const std::string stem = part.stem().string();   // "clip.part-0003-of-0008"
  std::size_t at = stem.rfind(".part-");
  std::size_t of = stem.rfind("-of-");
  if (at == std::string::npos || of == std::string::npos || of < at) return std::nullopt;
  std::optional<int> index = number(stem.substr(at + 6, of - at - 6));
  std::optional<int> count = number(stem.substr(of + 4));
  if (!index || !count || *count < 1 || *index < 1 || *index > *count) return std::nullopt;
  fs::path video = part;
  video.replace_filename(stem.substr(0, at) + part.extension().string());
  return VideoPartName{video, *index, *count};
}

JoinSummary joinVideoParts(const fs::path& output, const std::vector<fs::path>& parts, bool overwrite) {
  std::vector<fs::path> ordered = orderedParts(parts);
  checkReplaceable(output);
  std::error_code ec;
  if (!overwrite && fs::exists(output, ec)) throwCantWrite(output, "it already exists (add -y/--overwrite to replace it)");
  std::vector<OpenPart> opened;
  for (const fs::path& p : ordered) {
    opened.push_back(openPart(p));
    checkCompatible(opened.front(), opened.back());
  }

  const fs::path temp = temporarySibling(output, "join", /*keep_extension=*/true);
  JoinSummary summary;
  try {
    summary = writeJoined(temp, output, opened);
  } catch (...) {
    fs::remove(temp, ec);   // never half a video
    throw;
  }
  commitFile(temp, output, overwrite);
  return summary;
}

}  // namespace tumble
