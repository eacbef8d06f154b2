// Random blocks of whole cells on the document's 20 x 10 grid.
#include "worlds/cell_block_world.h"

#include <cstdio>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

#include "util/c_number.h"
#include "worlds/world_loader.h"

namespace plantsim::worlds {
namespace {

constexpr int kColumns = 20, kRows = 10;
constexpr double kCell = 2.0;

// The 2 x 2 cells at the start (bottom-left) and at the charger (top-left) stay free.
bool kept_free(int column, int row) { return column < 2 && (row < 2 || row >= kRows - 2); }

}  // namespace

World cell_block_world(const CellBlockOptions& o) {
  if (!(o.blocked_share >= 0 && o.blocked_share <= 0.5))
    throw std::invalid_argument("cell-block world: the blocked share must be between 0 and 0.5");
  std::mt19937_64 rng(o.seed);
  std::vector<std::vector<bool>> blocked(kColumns, std::vector<bool>(kRows, false));
  int count = 0;
  World w;
  while (count < o.blocked_share * kColumns * kRows) {
    const int bw = 1 + static_cast<int>(rng() % 3), bh = 1 + static_cast<int>(rng() % 2);
    const int c0 = static_cast<int>(rng() % (kColumns - bw + 1)),
              r0 = static_cast<int>(rng() % (kRows - bh + 1));
    for (int c = c0; c < c0 + bw; ++c)
      for (int r = r0; r < r0 + bh; ++r)
        if (!kept_free(c, r) && !blocked[c][r]) blocked[c][r] = true, ++count;
  }
  // One rectangle per blocked cell: the grid method needs no merging, and the cells are exact.
  for (int c = 0; c < kColumns; ++c)
    for (int r = 0; r < kRows; ++r)
      if (blocked[c][r])
        w.obstacles.push_back({c * kCell, r * kCell, (c + 1) * kCell, (r + 1) * kCell});
  char name[64];
  util::c_snprintf(name, sizeof name, "cell_blocks_%02.0f_seed%llu", 100 * o.blocked_share,
                   static_cast<unsigned long long>(o.seed));
  w.name = name;
  w.source = "generated (" + w.name + ")";
  w.floor = {0, 0, kColumns * kCell, kRows * kCell};
  w.robot.radius_m = 0.2;
  w.inflation_margin_m = 0.1;
  w.start = {1.0, 1.0, 0.0};
  w.charger = {0.35, 19.0, std::numbers::pi};
  validate_world(w);
  return w;
}

}  // namespace plantsim::worlds
