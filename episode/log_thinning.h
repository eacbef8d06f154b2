// Thinning a log to its limit: every other entry kept (the first among them), so that a log
// written half as often from then on still spans the whole episode at a fixed size.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace plantsim::episode {

template <class T>
void keep_every_other(std::vector<T>& log) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < log.size(); i += 2) log[kept++] = std::move(log[i]);
  log.resize(kept);
}

}  // namespace plantsim::episode
