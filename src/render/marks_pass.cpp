#include "render/marks_pass.h"

#include <cmath>

namespace tumble::render {
namespace {

constexpr float kOutline[3] = {0.08f, 0.08f, 0.08f};   // sRGB: near black
constexpr float kNearW = 1e-4f;                         // clip w below which a point is behind the eye

struct Screen {
  int width, height;
  Eigen::Vector2f pixels(const Eigen::Vector4f& clip) const {
    return {(clip.x() / clip.w() * 0.5f + 0.5f) * width, (clip.y() / clip.w() * 0.5f + 0.5f) * height};
  }
  void push(std::vector<float>& out, const Eigen::Vector2f& px, const float* rgb, float alpha = 1) const {
    out.insert(out.end(), {px.x() / width * 2 - 1, px.y() / height * 2 - 1, rgb[0], rgb[1], rgb[2], alpha});
  }
};

constexpr int kFloats = 6;   // per vertex: x, y, r, g, b, a

void quad(const Screen& s, Eigen::Vector2f a, Eigen::Vector2f b, float half, const float* rgb, std::vector<float>& out,
          float alpha = 1) {
  Eigen::Vector2f d = b - a;
  const float len = d.norm();
  d = len > 1e-6f ? Eigen::Vector2f(d / len) : Eigen::Vector2f(1, 0);
  const Eigen::Vector2f n(-d.y() * half, d.x() * half);
  a -= d * half;   // square caps: joined segments (an arrow's head) meet without a notch
  b += d * half;
  const Eigen::Vector2f corners[] = {a - n, b - n, b + n, a - n, b + n, a + n};
  for (const Eigen::Vector2f& p : corners) s.push(out, p, rgb, alpha);
}

void octagon(const Screen& s, const Eigen::Vector2f& c, float r, const float* rgb, std::vector<float>& out) {
  for (int k = 0; k < 8; ++k) {
    const float t0 = static_cast<float>(k) * 0.785398163f, t1 = t0 + 0.785398163f;
    s.push(out, c, rgb);
    s.push(out, c + r * Eigen::Vector2f(std::cos(t0), std::sin(t0)), rgb);
    s.push(out, c + r * Eigen::Vector2f(std::cos(t1), std::sin(t1)), rgb);
  }
}

// The segment in clip space, cut where it crosses w = kNearW; false when wholly behind the eye.
bool clipSegment(Eigen::Vector4f& a, Eigen::Vector4f& b) {
  if (a.w() < kNearW && b.w() < kNearW) return false;
  if (a.w() < kNearW) a = a + (b - a) * ((kNearW - a.w()) / (b.w() - a.w()));
  if (b.w() < kNearW) b = b + (a - b) * ((kNearW - b.w()) / (a.w() - b.w()));
  return true;
}

}  // namespace

void buildMarkTriangles(const DrawMarks& marks, const Eigen::Matrix4f& view_proj, int width, int height,
                        std::vector<float>& out) {
  out.clear();
  const Screen s{width, height};
  for (const DrawFaintSegment& seg : marks.faint) {   // under everything, no outline
    Eigen::Vector4f a = view_proj * seg.from.homogeneous(), b = view_proj * seg.to.homogeneous();
    if (clipSegment(a, b)) quad(s, s.pixels(a), s.pixels(b), marks.faint_px / 2, seg.colour.data(), out, seg.alpha);
  }
  std::vector<std::pair<Eigen::Vector2f, Eigen::Vector2f>> lines;
  std::vector<Eigen::Vector2f> dots;
  lines.reserve(marks.segments.size());
  dots.reserve(marks.dots.size());
  for (const DrawSegment& seg : marks.segments) {
    Eigen::Vector4f a = view_proj * seg.from.homogeneous(), b = view_proj * seg.to.homogeneous();
    lines.push_back(clipSegment(a, b) ? std::make_pair(s.pixels(a), s.pixels(b))
                                      : std::make_pair(Eigen::Vector2f(NAN, NAN), Eigen::Vector2f(NAN, NAN)));
  }
  for (const DrawDot& dot : marks.dots) {
    const Eigen::Vector4f c = view_proj * dot.at.homogeneous();
    dots.push_back(c.w() < kNearW ? Eigen::Vector2f(NAN, NAN) : s.pixels(c));
  }
  const float half = marks.line_px / 2, radius = marks.dot_px / 2, rim = marks.outline_px;
  for (int pass = 0; pass < 2; ++pass) {   // outlines under every mark, then the marks
    const float grow = pass == 0 ? rim : 0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (std::isnan(lines[i].first.x())) continue;
      quad(s, lines[i].first, lines[i].second, half + grow, pass == 0 ? kOutline : marks.segments[i].colour.data(), out);
    }
    for (std::size_t i = 0; i < dots.size(); ++i) {
      if (std::isnan(dots[i].x())) continue;
      octagon(s, dots[i], radius + grow, pass == 0 ? kOutline : marks.dots[i].colour.data(), out);
    }
  }
}

MarksPass::MarksPass() {
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, kFloats * sizeof(float), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, kFloats * sizeof(float), reinterpret_cast<void*>(2 * sizeof(float)));
  glBindVertexArray(0);
}

MarksPass::~MarksPass() {
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
}

void MarksPass::draw(const DrawMarks& marks, const Eigen::Matrix4f& view_proj, int width, int height,
                     const GlProgram& program) {
  buildMarkTriangles(marks, view_proj, width, height, vertices_);
  if (vertices_.empty()) return;
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  // Faint lines blend over the frame (in sRGB, as written); the marks have alpha 1 and replace it.
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  program.use();
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices_.size() * sizeof(float)), vertices_.data(),
               GL_STREAM_DRAW);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices_.size() / kFloats));
  glBindVertexArray(0);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace tumble::render
