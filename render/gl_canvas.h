// A headless OpenGL canvas on OSMesa (software rendering, no display, no GPU) with a
// world-to-pixel transform that keeps the aspect ratio. Draws filled rectangles, oriented
// boxes, disks and thick polylines in world coordinates; reads back an Image. Edges are smoothed
// either analytically (supersample 1: lines, disks and boxes carry a one-pixel rim whose opacity
// falls to zero, the coverage of a pixel by the shape) or by rendering at a multiple of the final
// size and averaging down. Axis-aligned rectangles stay crisp in both: tiles that share an edge
// must not show a seam.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/vec2.h"
#include "render/image.h"

namespace plantsim::render {

using geom::Rect;
using geom::Vec2;

/// Maps world metres into pixels of an image (row 0 at the top), same scale on both axes.
struct PixelTransform {
  double scale = 1;       ///< pixels per metre
  double x0 = 0, y0 = 0;  ///< pixel position (column, row from the bottom) of world (0, 0)
  int height = 0;         ///< image height, to flip rows
  /// Fits `view` into the box [left, right] x [bottom, top] pixels (rows counted from the bottom).
  static PixelTransform fit(const Rect& view, double left, double bottom, double right, double top,
                            int image_height);
  /// Column and row (row 0 at the top) of world point p.
  Vec2 to_pixel(Vec2 p) const { return {x0 + scale * p.x, height - (y0 + scale * p.y)}; }
};

class GlCanvas {
 public:
  GlCanvas(int width, int height, int supersample = 1);
  ~GlCanvas();
  GlCanvas(const GlCanvas&) = delete;
  GlCanvas& operator=(const GlCanvas&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }

  void clear(Rgb c);
  void set_transform(const PixelTransform& t) { transform_ = t; }
  /// Restricts drawing to the box of final-image pixels [left, right) x [top, bottom) (row 0 at
  /// the top), for insets; clear_clip() lifts it.
  void set_clip(double left, double top, double right, double bottom);
  void clear_clip();
  const PixelTransform& transform() const { return transform_; }
  struct Context;  ///< an OSMesa context and its frame buffer, reused by the next canvas

  void fill_rect(const Rect& r, Rgb c, float alpha = 1.0f);
  void fill_box(Vec2 center, double half_x, double half_y, double yaw, Rgb c);
  void fill_disk(Vec2 center, double radius_m, Rgb c);
  void ring(Vec2 center, double radius_m, double width_px, Rgb c);
  /// Thick polyline with round joins; width in final-image pixels.
  void polyline(const std::vector<Vec2>& pts, double width_px, Rgb c);
  /// Line segments between pixel coordinates of the final image (row 0 at the top).
  void pixel_line(Vec2 a, Vec2 b, double width_px, Rgb c);
  void pixel_polyline(const std::vector<Vec2>& pts, double width_px, Rgb c);
  /// Segment i of `pts` drawn in colours[i] (one fewer colour than points), round joins.
  void coloured_polyline(const std::vector<Vec2>& pts, const std::vector<Rgb>& colours,
                         double width_px);

  /// Waits until the drawing is done (for timing); read() does this too.
  void finish() const;
  Image read() const;

 private:
  struct BatchVertex {
    float x, y;
    std::uint8_t r, g, b, a;
  };
  void color(Rgb c, float alpha = 1.0f);
  /// `coverage` scales the current colour's opacity: 0 on the outer edge of a smoothing rim.
  void vertex(Vec2 p, float coverage = 1.0f);
  void triangle(Vec2 a, Vec2 b, Vec2 c);
  void quad(Vec2 a, Vec2 b, Vec2 c, Vec2 d);
  /// A band from the opaque edge a-b to the transparent edge c-d (its rim).
  void rim(Vec2 a, Vec2 b, Vec2 c, Vec2 d, float inner_coverage = 1.0f);
  void flush() const;
  void make_current() const;
  void quad_px(Vec2 a, Vec2 b, double width_px);  // in supersampled pixels, GL rows
  void disk_px(Vec2 center, double radius_px);
  Vec2 gl_px(Vec2 world) const;
  Vec2 pixel_to_gl(Vec2 image_px) const;
  /// Segments between GL-pixel points, width w; colours[i] for segment i when given (else the
  /// current colour); round joins where the line turns, round caps when asked.
  void stroke_px(const std::vector<Vec2>& pts, double w, const std::vector<Rgb>* colours,
                 bool round_caps);

  int width_, height_, ss_;
  bool smooth_edges_;  ///< analytic rims (no supersampling to average them)
  PixelTransform transform_;
  std::unique_ptr<Context> ctx_;
  std::array<std::uint8_t, 4> current_{0, 0, 0, 255};
  mutable std::vector<BatchVertex> batch_;
};

}  // namespace plantsim::render
