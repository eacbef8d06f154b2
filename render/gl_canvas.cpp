// OSMesa context management and the fixed-function GL drawing of primitives.
#include "render/gl_canvas.h"

#include <GL/gl.h>
#include <GL/osmesa.h>

#include <algorithm>
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
  glClearColor(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

Vec2 GlCanvas::gl_px(Vec2 p) const {
  return {ss_ * (transform_.x0 + transform_.scale * p.x), ss_ * (transform_.y0 + transform_.scale * p.y)};
}

static void color(Rgb c, float alpha = 1.0f) { glColor4f(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, alpha); }

void GlCanvas::fill_rect(const Rect& r, Rgb c, float alpha) {
  const Vec2 a = gl_px({r.xmin, r.ymin}), b = gl_px({r.xmax, r.ymax});
  color(c, alpha);
  glBegin(GL_QUADS);
  glVertex2d(a.x, a.y);
  glVertex2d(b.x, a.y);
  glVertex2d(b.x, b.y);
  glVertex2d(a.x, b.y);
  glEnd();
}

void GlCanvas::fill_box(Vec2 center, double half_x, double half_y, double yaw, Rgb c) {
  color(c);
  glBegin(GL_QUADS);
  for (Vec2 k : {Vec2{-1, -1}, Vec2{1, -1}, Vec2{1, 1}, Vec2{-1, 1}}) {
    const Vec2 p = gl_px(center + geom::rotate({k.x * half_x, k.y * half_y}, yaw));
    glVertex2d(p.x, p.y);
  }
  glEnd();
}

void GlCanvas::disk_px(Vec2 c, double r) {
  const int n = std::clamp(static_cast<int>(r * 1.5), 12, 96);
  glBegin(GL_TRIANGLE_FAN);
  glVertex2d(c.x, c.y);
  for (int i = 0; i <= n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    glVertex2d(c.x + r * std::cos(a), c.y + r * std::sin(a));
  }
  glEnd();
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
  glBegin(GL_QUADS);
  glVertex2d(a.x + n.x, a.y + n.y);
  glVertex2d(b.x + n.x, b.y + n.y);
  glVertex2d(b.x - n.x, b.y - n.y);
  glVertex2d(a.x - n.x, a.y - n.y);
  glEnd();
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

Image GlCanvas::read() const {
  glFinish();
  Image img;
  img.width = width_;
  img.height = height_;
  img.rgba.assign(static_cast<std::size_t>(width_) * height_ * 4, 255);
  const int w = width_ * ss_;
  const std::uint8_t* src = ctx_->buffer.data();
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
