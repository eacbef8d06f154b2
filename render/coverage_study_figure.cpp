// One row of three plots per obstacle share.
#include "render/coverage_study_figure.h"

#include <cstdio>

#include "render/palette.h"
#include "util/c_number.h"

namespace plantsim::render {

Image draw_coverage_study(const std::vector<StudyShare>& shares, const std::string& title,
                          const std::vector<std::string>& verdict_lines, int width_px,
                          FigureLayout* layout_out) {
  const int lines_px = 20 * static_cast<int>(verdict_lines.size());
  const int header_px = 50 + lines_px + 40, row_px = 330;
  Figure fig(width_px, header_px + row_px * static_cast<int>(shares.size()));
  fig.text_fitted(title, 20, 32, 20, palette::kAxis, width_px - 40.0, true);
  for (std::size_t i = 0; i < verdict_lines.size(); ++i)
    fig.text_fitted(verdict_lines[i], 20, 56 + 20.0 * i, 14, palette::kAxis, width_px - 40.0);
  // One legend for every plot: the methods keep their colours throughout.
  std::vector<LegendEntry> legend;
  if (!shares.empty())
    for (const StudyMethod& m : shares.front().methods) legend.push_back({m.colour, m.name});
  fig.legend(20, 50 + lines_px + 12, legend, static_cast<int>(legend.size()), 190);
  const double plot_w = (width_px - 60.0) / 3;
  for (std::size_t r = 0; r < shares.size(); ++r) {
    const StudyShare& s = shares[r];
    const double top = header_px + row_px * static_cast<double>(r);
    struct Measure {
      const char* name;
      const char* unit;
      std::vector<double> StudyMethod::*values;
    };
    const Measure measures[3] = {{"repetition", "%", &StudyMethod::repetition_percent},
                                 {"turns", "count", &StudyMethod::turns},
                                 {"dead ends", "count", &StudyMethod::dead_ends}};
    for (int k = 0; k < 3; ++k) {
      std::vector<Figure::Series> series;
      for (const StudyMethod& m : s.methods) {
        Figure::Series line{{}, m.*(measures[k].values), m.colour, m.name};
        for (std::size_t j = 0; j < line.y.size(); ++j) line.x.push_back(j + 1.0);
        series.push_back(std::move(line));
      }
      Figure::PlotOptions o;
      o.x_label = "map";
      o.legend = false;
      char plot_title[96];
      util::c_snprintf(plot_title, sizeof plot_title, "%.0f %% of cells blocked: %s",
                       100 * s.blocked_share, measures[k].name);
      const double left = 20 + plot_w * k + 55;
      fig.plot({left, top + 40, left + plot_w - 75, top + row_px - 50}, series, plot_title,
               measures[k].unit, o);
    }
  }
  Image img = fig.finish();
  if (layout_out) *layout_out = fig.layout();
  return img;
}

}  // namespace plantsim::render
