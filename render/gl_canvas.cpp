// OSMesa context management and the fixed-function GL drawing of primitives.
#include "render/gl_canvas.h"

#include <GL/gl.h>
#include <GL/osmesa.h>

#include <algorithm>
#include <cstring>
#include <cmath>
#include <stdexcept>

namespace plantsim::render {

PixelTransform PixelTransform::fit(const Rect& view, double left, double bottom, double right,
                                   double top, int image_height) {
  PixelTransform t;
  t.scale = std::min((right - left) / view.width(), (top - bottom) / view.height());
  const double used_w = t.scale * view.width(), used_h = t.scale * view.height();
  t.x0 = left + 0.5 * ((right - left) - used_w) - t.scale * view.xmin;
  t.y0 = bottom + 0.5 * ((top - bottom) - used_h) - t.scale * view.ymin;
  t.height = image_height;
  return t;
}

struct GlCanvas::Context {
  OSMesaContext mesa = nullptr;
  std::vector<std::uint8_t> buffer;
};

GlCanvas::GlCanvas(int width, int height, int supersample)
    : width_(width), height_(height), ss_(std::max(1, supersample)), ctx_(std::make_unique<Context>()) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    throw std::invalid_argument("image size must be between 1 and 16384 pixels a side");
  const int w = width_ * ss_, h = height_ * ss_;
  ctx_->mesa = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
  if (!ctx_->mesa) throw std::runtime_error("OSMesa: cannot create a context");
  ctx_->buffer.assign(static_cast<std::size_t>(w) * h * 4, 0);
  if (!OSMesaMakeCurrent(ctx_->mesa, ctx_->buffer.data(), GL_UNSIGNED_BYTE, w, h)) {
    OSMesaDestroyContext(ctx_->mesa);
    throw std::runtime_error("OSMesa: cannot bind the frame buffer");
  }
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, w, 0, h, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
}

GlCanvas::~GlCanvas() {
  if (ctx_ && ctx_->mesa) OSMesaDestroyContext(ctx_->mesa);
}

void GlCanvas::clear(Rgb c) {
  batch_.clear();
  glClearColor(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

Vec2 GlCanvas::gl_px(Vec2 p) const {
  return {ss_ * (transform_.x0 + transform_.scale * p.x), ss_ * (transform_.y0 + transform_.scale * p.y)};
}

void GlCanvas::color(Rgb c, float alpha) {
  current_ = {c.r, c.g, c.b, static_cast<std::uint8_t>(std::lround(std::clamp(alpha, 0.0f, 1.0f) * 255))};
}

void GlCanvas::vertex(double x, double y) {
  batch_.push_back({static_cast<float>(x), static_cast<float>(y), current_[0], current_[1], current_[2], current_[3]});
}

void GlCanvas::triangle(Vec2 a, Vec2 b, Vec2 c) {
  vertex(a.x, a.y);
  vertex(b.x, b.y);
  vertex(c.x, c.y);
}

void GlCanvas::quad(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  triangle(a, b, c);
  triangle(a, c, d);
}

// All geometry goes to GL as one array of coloured triangles: primitives are drawn in
// submission order, so the layer order holds, at the cost of one call instead of thousands.
void GlCanvas::flush() const {
  if (batch_.empty()) return;
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, sizeof(BatchVertex), &batch_[0].x);
  glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(BatchVertex), &batch_[0].r);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(batch_.size()));
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  batch_.clear();
}

void GlCanvas::set_clip(double left, double top, double right, double bottom) {
  flush();  // what was drawn before is not clipped
  const int x0 = static_cast<int>(std::floor(left * ss_)), x1 = static_cast<int>(std::ceil(right * ss_));
  const int y0 = static_cast<int>(std::floor((height_ - bottom) * ss_)), y1 = static_cast<int>(std::ceil((height_ - top) * ss_));
  glEnable(GL_SCISSOR_TEST);
  glScissor(x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0));
}

void GlCanvas::clear_clip() {
  flush();
  glDisable(GL_SCISSOR_TEST);
}

void GlCanvas::fill_rect(const Rect& r, Rgb c, float alpha) {
  const Vec2 a = gl_px({r.xmin, r.ymin}), b = gl_px({r.xmax, r.ymax});
  color(c, alpha);
  quad(a, {b.x, a.y}, b, {a.x, b.y});
}

void GlCanvas::fill_box(Vec2 center, double half_x, double half_y, double yaw, Rgb c) {
  color(c);
  Vec2 p[4];
  int i = 0;
  for (Vec2 k : {Vec2{-1, -1}, Vec2{1, -1}, Vec2{1, 1}, Vec2{-1, 1}})
    p[i++] = gl_px(center + geom::rotate({k.x * half_x, k.y * half_y}, yaw));
  quad(p[0], p[1], p[2], p[3]);
}

void GlCanvas::disk_px(Vec2 c, double r) {
  const int n = std::clamp(static_cast<int>(r * 1.5), r < 3.0 ? 6 : 12, 96);  // a few-pixel disk needs few sides
  Vec2 prev{c.x + r, c.y};
  for (int i = 1; i <= n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    const Vec2 next{c.x + r * std::cos(a), c.y + r * std::sin(a)};
    triangle(c, prev, next);
    prev = next;
  }
}

void GlCanvas::fill_disk(Vec2 center, double radius_m, Rgb c) {
  color(c);
  disk_px(gl_px(center), ss_ * transform_.scale * radius_m);
}

void GlCanvas::ring(Vec2 center, double radius_m, double width_px, Rgb c) {
  const int n = 64;
  std::vector<Vec2> pts;
  for (int i = 0; i <= n; ++i) pts.push_back(center + radius_m * geom::unit_from_angle(2.0 * M_PI * i / n));
  polyline(pts, width_px, c);
}

void GlCanvas::quad_px(Vec2 a, Vec2 b, double w) {
  const Vec2 d = b - a;
  const double len = geom::norm(d);
  if (len == 0) return;
  const Vec2 n = (0.5 * w / len) * Vec2{-d.y, d.x};
  quad(a + n, b + n, b - n, a - n);
}

void GlCanvas::polyline(const std::vector<Vec2>& pts, double width_px, Rgb c) {
  color(c);
  const double w = ss_ * width_px;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Vec2 p = gl_px(pts[i]);
    if (i > 0) quad_px(gl_px(pts[i - 1]), p, w);
    if (w > 2.0) disk_px(p, 0.5 * w);
  }
}

void GlCanvas::pixel_line(Vec2 a, Vec2 b, double width_px, Rgb c) {
  color(c);
  auto to_gl = [&](Vec2 p) { return Vec2{ss_ * p.x, ss_ * (height_ - p.y)}; };
  quad_px(to_gl(a), to_gl(b), ss_ * width_px);
}

void GlCanvas::pixel_polyline(const std::vector<Vec2>& pts, double width_px, Rgb c) {
  color(c);
  auto to_gl = [&](Vec2 p) { return Vec2{ss_ * p.x, ss_ * (height_ - p.y)}; };
  const double w = ss_ * width_px;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (i > 0) quad_px(to_gl(pts[i - 1]), to_gl(pts[i]), w);
    if (w > 2.0) disk_px(to_gl(pts[i]), 0.5 * w);
  }
}

void GlCanvas::coloured_polyline(const std::vector<Vec2>& pts, const std::vector<Rgb>& colours, double width_px) {
  const double w = ss_ * width_px;
  for (std::size_t i = 1; i < pts.size() && i - 1 < colours.size(); ++i) {
    color(colours[i - 1]);
    const Vec2 a = gl_px(pts[i - 1]), b = gl_px(pts[i]);
    quad_px(a, b, w);
    // A round join only where the line turns enough to open a visible notch.
    if (w > 2.0 && i + 1 < pts.size()) {
      const Vec2 d1 = b - a, d2 = gl_px(pts[i + 1]) - b;
      const double turn = std::fabs(geom::cross(d1, d2)) / std::max(geom::norm(d1) * geom::norm(d2), 1e-12);
      if (turn * w > 0.5) disk_px(b, 0.5 * w);
    }
  }
}

void GlCanvas::finish() const {
  flush();
  glFinish();
}

Image GlCanvas::read() const {
  finish();
  Image img;
  img.width = width_;
  img.height = height_;
  img.rgba.assign(static_cast<std::size_t>(width_) * height_ * 4, 255);
  const int w = width_ * ss_;
  const std::uint8_t* src = ctx_->buffer.data();
  if (ss_ == 1) {  // rows flipped, nothing to average
    const std::size_t row_bytes = static_cast<std::size_t>(width_) * 4;
    for (int row = 0; row < height_; ++row)
      std::memcpy(img.rgba.data() + row * row_bytes, src + static_cast<std::size_t>(height_ - 1 - row) * row_bytes, row_bytes);
    return img;
  }
  if (ss_ == 2) {  // the usual case: a 2x2 box filter over whole rows, no per-channel loops
    for (int row = 0; row < height_; ++row) {
      const std::uint8_t* a = src + static_cast<std::size_t>((height_ - 1 - row) * 2) * w * 4;
      const std::uint8_t* b = a + static_cast<std::size_t>(w) * 4;
      std::uint8_t* out = img.rgba.data() + static_cast<std::size_t>(row) * width_ * 4;
      for (int col = 0; col < width_; ++col, a += 8, b += 8, out += 4) {
        out[0] = static_cast<std::uint8_t>((a[0] + a[4] + b[0] + b[4] + 2) >> 2);
        out[1] = static_cast<std::uint8_t>((a[1] + a[5] + b[1] + b[5] + 2) >> 2);
        out[2] = static_cast<std::uint8_t>((a[2] + a[6] + b[2] + b[6] + 2) >> 2);
      }
    }
    return img;
  }
  const int n = ss_ * ss_;
  for (int row = 0; row < height_; ++row) {
    const int gl_row0 = (height_ - 1 - row) * ss_;  // OSMesa rows start at the bottom
    for (int col = 0; col < width_; ++col) {
      for (int ch = 0; ch < 3; ++ch) {
        int sum = 0;
        for (int dy = 0; dy < ss_; ++dy)
          for (int dx = 0; dx < ss_; ++dx)
            sum += src[(static_cast<std::size_t>(gl_row0 + dy) * w + col * ss_ + dx) * 4 + ch];
        img.rgba[(static_cast<std::size_t>(row) * width_ + col) * 4 + ch] =
            static_cast<std::uint8_t>((sum + n / 2) / n);
      }
    }
  }
  return img;
}

}  // namespace plantsim::render
