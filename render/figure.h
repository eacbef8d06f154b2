// A figure: one GL canvas for the drawing and text composited over it when finished, plus the
// pieces every plantsim figure shares: panels that map a world or a plot into a pixel box,
// axes with ticks and numbers, titles, legends and colour bars.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "render/gl_canvas.h"
#include "render/text.h"

namespace plantsim::render {

/// A box of pixels, row 0 at the top.
struct PixelBox {
  double left = 0, top = 0, right = 0, bottom = 0;
  double width() const { return right - left; }
  double height() const { return bottom - top; }
};

/// How a legend entry's swatch is drawn: like the mark it names, so that two entries of one colour
/// (the charger and where the map puts it; a stop and the first plan) are still told apart.
enum class Swatch { kBar, kDashed, kRing, kDot, kOutline };

struct LegendEntry {
  Rgb colour;
  std::string label;
  Swatch swatch = Swatch::kBar;
};

/// A legend of what panels drew: an entry only when its layer was drawn, each label once.
class UniqueLegend {
 public:
  void operator()(bool drawn, Rgb colour, const std::string& label) {
    for (const LegendEntry& e : entries)
      if (e.label == label) return;
    if (drawn) entries.push_back({colour, label});
  }
  std::vector<LegendEntry> entries;
};

/// What a finished figure put where, for tests: every text's box, every legend entry and the
/// boxes legends and insets cover (a legend swatch is not evidence that its layer was drawn).
struct FigureLayout {
  std::vector<std::string> texts;
  std::vector<TextBox> text_boxes;
  std::vector<LegendEntry> legend;
  std::vector<PixelBox> legend_boxes;
  std::vector<PixelBox> insets;
};

/// Whether two text boxes share a pixel.
bool overlaps(const TextBox& a, const TextBox& b);

/// Panels in a grid under a title line: at most `max_columns` a row, each `panel_height_px`
/// high and an equal share of the width.
struct PanelGrid {
  int columns = 1, rows = 1;
  double panel_width_px = 0;
  int panel_height_px = 0;
  int top_px = 50;
  int height_px() const { return top_px + rows * panel_height_px; }
  /// Top-left corner of panel i, in pixels.
  Vec2 corner(std::size_t i) const {
    return {panel_width_px * static_cast<double>(i % columns),
            top_px + panel_height_px * static_cast<double>(i / columns)};
  }
};
PanelGrid panel_grid(std::size_t panels, int max_columns, int width_px, int panel_height_px);

class Figure {
 public:
  Figure(int width, int height, int supersample = 1);
  GlCanvas& canvas() { return canvas_; }
  int width() const { return canvas_.width(); }
  int height() const { return canvas_.height(); }

  /// Text is queued and drawn over the picture by finish().
  void text(const std::string& s, double x, double baseline_y, int size_px, Rgb colour,
            Anchor anchor = Anchor::kLeft, bool bold = false);
  /// `s` shortened with "..." (whole characters) to at most `max_width_px` at this size.
  std::string fit(const std::string& s, int size_px, double max_width_px, bool bold = false) const;
  /// As text(), shortened with "..." to at most `max_width_px` (long world names, settings).
  void text_fitted(const std::string& s, double x, double baseline_y, int size_px, Rgb colour,
                   double max_width_px, bool bold = false);
  /// As text(), unless it would overlap text already placed (annotations such as time ticks,
  /// which may crowd where the robot stood still); returns whether it was placed.
  bool text_if_free(const std::string& s, double x, double baseline_y, int size_px, Rgb colour,
                    Anchor anchor = Anchor::kLeft);
  /// Marks a box as an inset (a close-up drawn over the figure), for layout checks.
  void note_inset(const PixelBox& box) { layout_.insets.push_back(box); }

  /// Fits `view` (world metres) into `box` keeping the aspect ratio; sets the canvas transform.
  PixelTransform world_panel(const geom::Rect& view, const PixelBox& box);
  /// Restricts drawing to `view` (a few pixels beyond, for lines on its edge) until
  /// world_axes(): what perception placed off the floor (a lost estimate, stray returns) must
  /// not run over the legend.
  void clip_to_world(const geom::Rect& view, const PixelTransform& t, double margin_px = 4);
  /// Ticks and numbers along the bottom and left of a world panel, with axis labels (lifts the
  /// clip first).
  void world_axes(const geom::Rect& view, const PixelTransform& t);

  /// A colour bar of cividis from lo to hi, horizontal, in `box`, with ticks under it and a label
  /// above.
  void colour_bar(const PixelBox& box, double lo, double hi, const std::string& label);
  /// A legend of coloured swatches, one row each, starting at (x, y), in `columns` columns of
  /// `column_width_px`; returns the box it covers.
  PixelBox legend(double x, double y, const std::vector<LegendEntry>& entries, int columns = 1,
                  double column_width_px = 150);

  /// A line plot of (x, y) series in `box` with its own axes; series share the scales.
  struct Series {
    std::vector<double> x, y;
    Rgb colour;
    std::string label;
  };
  /// A shaded stretch of the x axis (a phase of the run), listed in the plot's legend.
  struct Band {
    double x0, x1;
    Rgb colour;
    std::string label;
  };
  struct PlotOptions {
    std::string x_label;  ///< empty: no label (stacked plots label the bottom one)
    std::vector<Band> bands;
    bool legend = false;    ///< series and bands named at the top right
    double min_y_span = 0;  ///< never zoom into less than this (noise around zero)
    std::string note;       ///< said in the middle when no series has a value
    /// Events at an instant (a kidnap, the failure): a vertical line across the plot in `colour`,
    /// named in the legend by `label`.
    struct Marker {
      double x;
      Rgb colour;
      std::string label;
    };
    std::vector<Marker> markers;
  };
  void plot(const PixelBox& box, const std::vector<Series>& series, const std::string& title,
            const std::string& y_label, const PlotOptions& options);

  /// Reads back the drawing and composites the queued text.
  Image finish();
  const FigureLayout& layout() const { return layout_; }

 private:
  void draw_swatch(double x, double y, const LegendEntry& e);
  void plot_axes(const PixelBox& box, double xmin, double xmax, double ymin, double ymax);
  void plot_legend(const PixelBox& box, const std::vector<Series>& series,
                   const std::vector<Band>& bands,
                   const std::vector<PlotOptions::Marker>& markers = {});
  struct QueuedText {
    std::string s;
    double x, y;
    int size;
    Rgb colour;
    Anchor anchor;
    bool bold;
  };
  GlCanvas canvas_;
  std::vector<QueuedText> texts_;
  FigureLayout layout_;
};

/// The shared text renderer (fonts are loaded once per process).
TextRenderer& shared_text_renderer();

}  // namespace plantsim::render
