// OSMesa context management and the fixed-function GL drawing of primitives.
#include "render/gl_canvas.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "render/osmesa_library.h"

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
  Context() = default;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  ~Context() {
    if (mesa) osmesa().destroy_context(mesa);
  }
};

namespace {

// A new OSMesa context compiles llvmpipe's shaders again, which costs as much as drawing a
// figure; figures come one after another, so each thread keeps the contexts it released.
thread_local std::vector<std::unique_ptr<GlCanvas::Context>> idle_contexts;

}  // namespace

GlCanvas::GlCanvas(int width, int height, int supersample)
    : width_(width), height_(height), ss_(std::max(1, supersample)), smooth_edges_(ss_ == 1) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    throw std::invalid_argument("image size must be between 1 and 16384 pixels a side");
  const int w = width_ * ss_, h = height_ * ss_;
  const OsMesaLibrary& gl = osmesa();
  if (!idle_contexts.empty()) {
    ctx_ = std::move(idle_contexts.back());
    idle_contexts.pop_back();
  } else {
    ctx_ = std::make_unique<Context>();
    ctx_->mesa = gl.create_context_ext(OSMESA_RGBA, 0, 0, 0, nullptr);
    if (!ctx_->mesa) throw std::runtime_error("OSMesa: cannot create a context");
  }
  ctx_->buffer.resize(static_cast<std::size_t>(w) * h * 4);
  if (!gl.make_current(ctx_->mesa, ctx_->buffer.data(), GL_UNSIGNED_BYTE, w, h))
    throw std::runtime_error("OSMesa: cannot bind the frame buffer");
  // A reused context keeps its state: set all of it.
  gl.viewport(0, 0, w, h);
  gl.matrix_mode(GL_PROJECTION);
  gl.load_identity();
  gl.ortho(0, w, 0, h, -1, 1);
  gl.matrix_mode(GL_MODELVIEW);
  gl.load_identity();
  gl.disable(GL_DEPTH_TEST);
  gl.disable(GL_SCISSOR_TEST);
  gl.enable(GL_BLEND);
  gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  gl.clear_color(0, 0, 0, 0);
  gl.clear(GL_COLOR_BUFFER_BIT);
}

GlCanvas::~GlCanvas() {
  if (!ctx_) return;
  // Kept for the next canvas: two are enough for a canvas made while another is alive. A frame
  // buffer over 64 MB (a poster-sized figure) is not held on to between figures.
  constexpr std::size_t kKeptBufferBytes = 64u << 20;
  if (idle_contexts.size() < 2 && ctx_->buffer.size() <= kKeptBufferBytes)
    idle_contexts.push_back(std::move(ctx_));
}

// Two canvases alive in one thread share GL's notion of "current": each binds its own
// context before it talks to GL.
void GlCanvas::make_current() const {
  const OsMesaLibrary& gl = osmesa();
  if (gl.get_current_context() != ctx_->mesa &&
      !gl.make_current(ctx_->mesa, ctx_->buffer.data(), GL_UNSIGNED_BYTE, width_ * ss_,
                       height_ * ss_))
    throw std::runtime_error("OSMesa: cannot bind the frame buffer");
}

void GlCanvas::clear(Rgb c) {
  const OsMesaLibrary& gl = osmesa();
  batch_.clear();
  make_current();
  gl.clear_color(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, 1.0f);
  gl.clear(GL_COLOR_BUFFER_BIT);
}

Vec2 GlCanvas::gl_px(Vec2 p) const {
  return {ss_ * (transform_.x0 + transform_.scale * p.x),
          ss_ * (transform_.y0 + transform_.scale * p.y)};
}

void GlCanvas::color(Rgb c, float alpha) {
  current_ = {c.r, c.g, c.b,
              static_cast<std::uint8_t>(std::lround(std::clamp(alpha, 0.0f, 1.0f) * 255))};
}

void GlCanvas::vertex(Vec2 p, float coverage) {
  const auto alpha =
      static_cast<std::uint8_t>(std::lround(current_[3] * std::clamp(coverage, 0.0f, 1.0f)));
  batch_.push_back({static_cast<float>(p.x), static_cast<float>(p.y), current_[0], current_[1],
                    current_[2], alpha});
}

void GlCanvas::triangle(Vec2 a, Vec2 b, Vec2 c) {
  vertex(a);
  vertex(b);
  vertex(c);
}

// Opacity interpolates linearly across the band: with a band one pixel wide, that is the
// fraction of each pixel the shape covers.
void GlCanvas::rim(Vec2 a, Vec2 b, Vec2 c, Vec2 d, float inner_coverage) {
  vertex(a, inner_coverage);
  vertex(b, inner_coverage);
  vertex(c, 0.0f);
  vertex(a, inner_coverage);
  vertex(c, 0.0f);
  vertex(d, 0.0f);
}

void GlCanvas::quad(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  triangle(a, b, c);
  triangle(a, c, d);
}

// All geometry goes to GL as one array of coloured triangles: primitives are drawn in
// submission order, so the layer order holds, at the cost of one call instead of thousands.
void GlCanvas::flush() const {
  const OsMesaLibrary& gl = osmesa();
  if (batch_.empty()) return;
  make_current();
  gl.enable_client_state(GL_VERTEX_ARRAY);
  gl.enable_client_state(GL_COLOR_ARRAY);
  gl.vertex_pointer(2, GL_FLOAT, sizeof(BatchVertex), &batch_[0].x);
  gl.color_pointer(4, GL_UNSIGNED_BYTE, sizeof(BatchVertex), &batch_[0].r);
  gl.draw_arrays(GL_TRIANGLES, 0, static_cast<GLsizei>(batch_.size()));
  gl.disable_client_state(GL_COLOR_ARRAY);
  gl.disable_client_state(GL_VERTEX_ARRAY);
  batch_.clear();
}

void GlCanvas::set_clip(double left, double top, double right, double bottom) {
  const OsMesaLibrary& gl = osmesa();
  flush();  // what was drawn before is not clipped
  make_current();
  const int x0 = static_cast<int>(std::floor(left * ss_)),
            x1 = static_cast<int>(std::ceil(right * ss_));
  const int y0 = static_cast<int>(std::floor((height_ - bottom) * ss_)),
            y1 = static_cast<int>(std::ceil((height_ - top) * ss_));
  gl.enable(GL_SCISSOR_TEST);
  gl.scissor(x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0));
}

void GlCanvas::clear_clip() {
  flush();
  make_current();
  osmesa().disable(GL_SCISSOR_TEST);
}

void GlCanvas::fill_rect(const Rect& r, Rgb c, float alpha) {
  const Vec2 a = gl_px({r.xmin, r.ymin}), b = gl_px({r.xmax, r.ymax});
  color(c, alpha);
  quad(a, {b.x, a.y}, b, {a.x, b.y});
}

void GlCanvas::fill_box(Vec2 center, double half_x, double half_y, double yaw, Rgb c) {
  color(c);
  const Vec2 mid = gl_px(center);
  const double hx = ss_ * transform_.scale * half_x, hy = ss_ * transform_.scale * half_y;
  auto corners = [&](double grow) {
    std::array<Vec2, 4> p;
    int i = 0;
    for (Vec2 k : {Vec2{-1, -1}, Vec2{1, -1}, Vec2{1, 1}, Vec2{-1, 1}})
      p[i++] =
          mid + geom::rotate({k.x * std::max(hx + grow, 0.0), k.y * std::max(hy + grow, 0.0)}, yaw);
    return p;
  };
  if (!smooth_edges_) {
    const auto p = corners(0.0);
    quad(p[0], p[1], p[2], p[3]);
    return;
  }
  // An opaque core shrunk by half a pixel and a rim grown by half a pixel; a box thinner than
  // a pixel is rim only, its peak opacity the share of a pixel it covers.
  const float peak = static_cast<float>(std::min(1.0, 2.0 * std::min(hx, hy)));
  const auto inner = corners(-0.5), outer = corners(0.5);
  if (peak >= 1.0f) quad(inner[0], inner[1], inner[2], inner[3]);
  for (int i = 0; i < 4; ++i) rim(inner[i], inner[(i + 1) % 4], outer[(i + 1) % 4], outer[i], peak);
}

void GlCanvas::disk_px(Vec2 c, double r) {
  const int n = std::clamp(static_cast<int>(r * 1.5), r < 3.0 ? 6 : 12,
                           96);  // a few-pixel disk needs few sides
  // Smoothed: an opaque core to r - 1/2 and a rim to r + 1/2; a disk under a pixel is rim only.
  const double r_in = smooth_edges_ ? std::max(r - 0.5, 0.0) : r, r_out = r + 0.5;
  const float core = smooth_edges_ ? static_cast<float>(std::min(1.0, 2.0 * r)) : 1.0f;
  Vec2 prev{1, 0};
  for (int i = 1; i <= n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    const Vec2 next{std::cos(a), std::sin(a)};
    if (r_in > 0) {
      vertex(c, core);
      vertex(c + r_in * prev, core);
      vertex(c + r_in * next, core);
    }
    if (smooth_edges_)
      rim(c + r_in * prev, c + r_in * next, c + r_out * next, c + r_out * prev, core);
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
  for (int i = 0; i <= n; ++i)
    pts.push_back(center + radius_m * geom::unit_from_angle(2.0 * M_PI * i / n));
  polyline(pts, width_px, c);
}

void GlCanvas::quad_px(Vec2 a, Vec2 b, double w) {
  const Vec2 d = b - a;
  const double len = geom::norm(d);
  if (len == 0) return;
  const Vec2 unit_normal = (1.0 / len) * Vec2{-d.y, d.x};
  if (!smooth_edges_) {
    const Vec2 n = 0.5 * w * unit_normal;
    quad(a + n, b + n, b - n, a - n);
    return;
  }
  // An opaque core w - 1 wide and a one-pixel rim each side; a line under a pixel wide is a
  // tent two pixels wide whose peak is its width, so it still carries its share of ink.
  const double half_core = std::max(0.5 * w - 0.5, 0.0), half_out = std::max(0.5 * w + 0.5, 1.0);
  const float peak = static_cast<float>(std::min(w, 1.0));
  const Vec2 n_in = half_core * unit_normal, n_out = half_out * unit_normal;
  if (half_core > 0) quad(a + n_in, b + n_in, b - n_in, a - n_in);
  rim(a + n_in, b + n_in, b + n_out, a + n_out, peak);
  rim(a - n_in, b - n_in, b - n_out, a - n_out, peak);
}

void GlCanvas::polyline(const std::vector<Vec2>& pts, double width_px, Rgb c) {
  color(c);
  std::vector<Vec2> gl;
  gl.reserve(pts.size());
  for (Vec2 p : pts) gl.push_back(gl_px(p));
  stroke_px(gl, ss_ * width_px, nullptr, true);
}

void GlCanvas::pixel_line(Vec2 a, Vec2 b, double width_px, Rgb c) {
  color(c);
  quad_px(pixel_to_gl(a), pixel_to_gl(b), ss_ * width_px);
}

void GlCanvas::pixel_polyline(const std::vector<Vec2>& pts, double width_px, Rgb c) {
  color(c);
  std::vector<Vec2> gl;
  gl.reserve(pts.size());
  for (Vec2 p : pts) gl.push_back(pixel_to_gl(p));
  stroke_px(gl, ss_ * width_px, nullptr, true);
}

void GlCanvas::coloured_polyline(const std::vector<Vec2>& pts, const std::vector<Rgb>& colours,
                                 double width_px) {
  std::vector<Vec2> gl;
  gl.reserve(pts.size());
  for (Vec2 p : pts) gl.push_back(gl_px(p));
  stroke_px(gl, ss_ * width_px, &colours, false);
}

Vec2 GlCanvas::pixel_to_gl(Vec2 p) const { return {ss_ * p.x, ss_ * (height_ - p.y)}; }

namespace {

// Which points to keep so that the line moves by at most `tolerance` pixels (Douglas-Peucker
// between consecutive pinned points; the ends are pinned). A path of thousands of sub-pixel
// samples costs triangles without changing a pixel.
std::vector<std::size_t> points_to_keep(const std::vector<Vec2>& pts, double tolerance,
                                        const std::vector<bool>& pinned) {
  std::vector<bool> keep(pts.size(), false);
  std::vector<std::pair<std::size_t, std::size_t>> spans;
  std::size_t from = 0;
  for (std::size_t i = 1; i < pts.size(); ++i)
    if (pinned[i] || i + 1 == pts.size()) {
      spans.push_back({from, i});
      from = i;
    }
  if (!pts.empty()) keep.front() = keep.back() = true;
  while (!spans.empty()) {
    const auto [lo, hi] = spans.back();
    spans.pop_back();
    keep[lo] = keep[hi] = true;
    const Vec2 d = pts[hi] - pts[lo];
    const double len = geom::norm(d);
    double worst = -1;
    std::size_t worst_at = lo;
    for (std::size_t i = lo + 1; i < hi; ++i) {
      const double off = len > 0 ? std::fabs(geom::cross(d, pts[i] - pts[lo])) / len
                                 : geom::norm(pts[i] - pts[lo]);
      if (off > worst) worst = off, worst_at = i;
    }
    if (worst > tolerance) {
      spans.push_back({lo, worst_at});
      spans.push_back({worst_at, hi});
    }
  }
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (keep[i]) kept.push_back(i);
  return kept;
}

bool visibly_different(Rgb a, Rgb b) {
  return std::abs(a.r - b.r) > 2 || std::abs(a.g - b.g) > 2 || std::abs(a.b - b.b) > 2;
}

}  // namespace

void GlCanvas::stroke_px(const std::vector<Vec2>& all_pts, double w,
                         const std::vector<Rgb>* colours, bool round_caps) {
  // A colour change pins its point; segments merged into one take the first one's colour.
  const std::size_t n_all =
      colours ? std::min(all_pts.size(), colours->size() + 1) : all_pts.size();
  std::vector<bool> pinned(n_all, false);
  if (colours)
    for (std::size_t i = 1, run_start = 0; i + 1 < n_all; ++i)
      if (visibly_different((*colours)[i], (*colours)[run_start])) pinned[i] = true, run_start = i;
  std::vector<Vec2> pts(all_pts.begin(), all_pts.begin() + static_cast<std::ptrdiff_t>(n_all));
  const std::vector<std::size_t> kept = points_to_keep(pts, 0.1, pinned);
  const bool caps = round_caps && w > 2.0;  // a thinner line's flat end is the same to the eye
  if (caps && !kept.empty()) disk_px(pts[kept.front()], 0.5 * w);
  for (std::size_t k = 1; k < kept.size(); ++k) {
    if (colours) color((*colours)[kept[k - 1]]);
    const Vec2 a = pts[kept[k - 1]], b = pts[kept[k]];
    quad_px(a, b, w);
    if (k + 1 == kept.size()) {
      if (caps) disk_px(b, 0.5 * w);
      continue;
    }
    // A round join only where the line turns enough to open a visible notch (its width is
    // about w/2 times the sine of the turn), thin lines included: simplified, a sharp corner
    // is one vertex, with no short samples left to fill it.
    const Vec2 d1 = b - a, d2 = pts[kept[k + 1]] - b;
    const double turn =
        std::fabs(geom::cross(d1, d2)) / std::max(geom::norm(d1) * geom::norm(d2), 1e-12);
    if (turn * w > 0.5 || geom::dot(d1, d2) < 0) disk_px(b, 0.5 * w);
  }
}

void GlCanvas::finish() const {
  flush();
  make_current();
  osmesa().finish();
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
      std::memcpy(img.rgba.data() + row * row_bytes,
                  src + static_cast<std::size_t>(height_ - 1 - row) * row_bytes, row_bytes);
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
