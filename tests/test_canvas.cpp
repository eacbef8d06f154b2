// The canvas's edges at 1x: a line's rim carries the share of each pixel it covers, tiles that
// share an edge show no seam, a path of thousands of samples still passes through every one,
// and two canvases alive at once keep their own drawings.
#include <gtest/gtest.h>

#include <cmath>

#include "render/colour_vision.h"
#include "render/gl_canvas.h"
#include "render/palette.h"

namespace plantsim::render {
namespace {

constexpr Rgb kWhite{255, 255, 255}, kBlack{0, 0, 0};

int red_at(const Image& img, int col, int row) {
  return img.rgba[(static_cast<std::size_t>(row) * img.width + col) * 4];
}

// World metres are pixels, y up from the bottom row.
void one_metre_per_pixel(GlCanvas& c) {
  const double w = c.width(), h = c.height();
  c.set_transform(PixelTransform::fit({0, 0, w, h}, 0, 0, w, h, c.height()));
  c.clear(kWhite);
}

TEST(Canvas, ALineHalfAPixelOffCoversItsTwoRowsHalfEach) {
  GlCanvas c(40, 20);
  one_metre_per_pixel(c);
  // A 1-px horizontal line centred on the boundary between rows 9 and 10 (y = 10 from the bottom).
  c.polyline({{5, 10}, {35, 10}}, 1.0, kBlack);
  const Image img = c.read();
  for (int row : {9, 10}) EXPECT_NEAR(red_at(img, 20, row), 128, 12) << row;  // half covered each
  EXPECT_EQ(red_at(img, 20, 5), 255);
  EXPECT_EQ(red_at(img, 20, 14), 255);
  // The ink is conserved: one pixel's worth across the column.
  double ink = 0;
  for (int row = 0; row < 20; ++row) ink += (255 - red_at(img, 20, row)) / 255.0;
  EXPECT_NEAR(ink, 1.0, 0.1);
}

TEST(Canvas, AThickLineIsOpaqueInsideAndSoftOnlyAtItsRim) {
  GlCanvas c(60, 60);
  one_metre_per_pixel(c);
  c.polyline({{5, 5}, {55, 50}}, 6.0, kBlack);
  const Image img = c.read();
  // On the centre line: solid; 6 px away across the line: untouched; between: some grey.
  const double len = std::hypot(50.0, 45.0), nx = -45.0 / len, ny = 50.0 / len;
  auto at = [&](double off) {
    const double x = 30 + off * nx, y = 27.5 + off * ny;
    return red_at(img, static_cast<int>(x), 60 - 1 - static_cast<int>(y));
  };
  EXPECT_EQ(at(0), 0);
  EXPECT_EQ(at(6), 255);
  int grey = 0;
  for (int col = 0; col < 60; ++col)
    for (int row = 0; row < 60; ++row)
      grey += red_at(img, col, row) > 10 && red_at(img, col, row) < 245;
  EXPECT_GT(grey, 50);  // the rims: two edges ~67 px long
}

TEST(Canvas, TilesSharingAnEdgeShowNoSeam) {
  GlCanvas c(40, 20);
  one_metre_per_pixel(c);
  for (double x = 3.3; x < 36; x += 2.7) c.fill_rect({x, 4.6, x + 2.7, 15.2}, kBlack);
  const Image img = c.read();
  for (int col = 5; col < 35; ++col) EXPECT_EQ(red_at(img, col, 10), 0) << col;
}

TEST(Canvas, AFinelySampledPathStillPassesThroughEverySample) {
  GlCanvas c(200, 200);
  one_metre_per_pixel(c);
  std::vector<Vec2> path;
  for (int i = 0; i <= 4000; ++i) {
    const double a = 2 * M_PI * i / 4000.0;
    path.push_back({100 + 70 * std::cos(a) + 8 * std::sin(9 * a), 100 + 70 * std::sin(a)});
  }
  c.polyline(path, 2.0, kBlack);
  const Image img = c.read();
  for (std::size_t i = 0; i < path.size(); i += 37)
    EXPECT_LT(red_at(img, static_cast<int>(path[i].x), 200 - 1 - static_cast<int>(path[i].y)), 128)
        << i;
}

TEST(Canvas, TwoCanvasesAliveAtOnceKeepTheirOwnDrawings) {
  GlCanvas a(20, 20);
  one_metre_per_pixel(a);
  GlCanvas b(30, 10);
  one_metre_per_pixel(b);
  a.fill_rect({0, 0, 20, 20}, kBlack);  // drawn after b was made current
  b.fill_rect({0, 0, 10, 10}, Rgb{128, 128, 128});
  const Image ia = a.read(), ib = b.read();
  EXPECT_EQ(red_at(ia, 10, 10), 0);
  EXPECT_EQ(red_at(ib, 5, 5), 128);
  EXPECT_EQ(red_at(ib, 25, 5), 255);  // a's black never reached b
}

// The simulation on known answers: grey stays grey, pure red and green meet under deuteranopia.
TEST(ColourVision, SimulationOnKnownAnswers) {
  for (ColourVision v :
       {ColourVision::kDeuteranopia, ColourVision::kProtanopia, ColourVision::kTritanopia}) {
    const Rgb grey = simulate({128, 128, 128}, v);
    EXPECT_NEAR(grey.r, 128, 1);
    EXPECT_NEAR(grey.g, 128, 1);
    EXPECT_NEAR(grey.b, 128, 1);
  }
  EXPECT_LT(colour_difference(simulate({200, 60, 0}, ColourVision::kDeuteranopia),
                              simulate({110, 110, 0}, ColourVision::kDeuteranopia)),
            colour_difference(Rgb{200, 60, 0}, Rgb{110, 110, 0}) / 3);
  EXPECT_NEAR(colour_difference({0, 0, 0}, {255, 255, 255}), 100.0, 0.1);  // L* from 0 to 100
  // Tritanopia confuses blue with green, not red with green (Okabe-Ito's blue and bluish green).
  const Rgb blue{0, 114, 178}, green{0, 158, 115}, red{213, 94, 0};
  EXPECT_LT(colour_difference(simulate(blue, ColourVision::kTritanopia),
                              simulate(green, ColourVision::kTritanopia)),
            colour_difference(blue, green) / 3);
  EXPECT_GT(colour_difference(simulate(red, ColourVision::kTritanopia),
                              simulate(green, ColourVision::kTritanopia)),
            0.6 * colour_difference(red, green));
}

// The pairs a reader must tell apart in one figure, as every reader sees them: failed paths and
// their start dots (batch overlays); failing, unsure and passing success bars; the estimate, the
// footprints of the driven path and the last scan (run figures); the plan and the charger.
TEST(ColourVision, ThePalettesPairsStayApartUnderDeuteranopiaAndProtanopia) {
  using namespace palette;
  const struct {
    const char* what;
    Rgb a, b;
  } pairs[] = {{"failed path / start", kFailure, kStart},
               {"failing bar / unsure bar", kFailure, kUnsureBar},
               {"unsure bar / passing bar", kUnsureBar, kCharger},
               {"failing bar / passing bar", kFailure, kCharger},
               {"estimate / footprints", kEstimate, kFootprint},
               {"estimate / last scan", kEstimate, kScan},
               {"footprints / last scan", kFootprint, kScan},
               {"plan / charger", kPlan, kCharger},
               {"driven path / failed path", kTrajectory, kFailure}};
  for (const auto& p : pairs)
    for (ColourVision v :
         {ColourVision::kNormal, ColourVision::kDeuteranopia, ColourVision::kProtanopia})
      EXPECT_GE(colour_difference(simulate(p.a, v), simulate(p.b, v)), 20.0)
          << p.what << " under vision " << static_cast<int>(v);
}

}  // namespace
}  // namespace plantsim::render
