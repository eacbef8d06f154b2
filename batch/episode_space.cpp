// A scenario's episodes by index and by id (see the header).
#include "batch/episode_space.h"

#include <array>
#include <stdexcept>

namespace plantsim::batch {
namespace {

template <class List, class Name>
std::unordered_map<std::string, std::size_t> positions(const List& list, Name name) {
  std::unordered_map<std::string, std::size_t> out;
  for (std::size_t i = 0; i < list.size(); ++i) out.emplace(name(list[i]), i);
  return out;
}

}  // namespace

EpisodeSpace::EpisodeSpace(const BatchSpec& spec, std::vector<std::string> world_names)
    : spec_(spec), world_names_(std::move(world_names)) {
  size_ =
      static_cast<std::int64_t>(world_names_.size() * spec.planners.size() *
                                spec.controllers.size() * spec.faults.size() * spec.seeds.size());
  world_ = positions(world_names_, [](const std::string& s) { return s; });
  planner_ = positions(spec.planners, [](const std::string& s) { return s; });
  controller_ = positions(spec.controllers, [](const NamedConfig& c) { return c.name; });
  fault_ = positions(spec.faults, [](const FaultSetting& f) { return f.name; });
  for (std::size_t i = 0; i < spec.seeds.size(); ++i) seed_.emplace(spec.seeds[i], i);
}

Episode EpisodeSpace::at(std::int64_t index) const {
  Episode e;
  e.index = index;
  auto next = [&index](std::size_t count) {
    const auto at = static_cast<std::size_t>(index % static_cast<std::int64_t>(count));
    index /= static_cast<std::int64_t>(count);
    return at;
  };
  e.seed = spec_.seeds[next(spec_.seeds.size())];
  e.fault = next(spec_.faults.size());
  e.controller = next(spec_.controllers.size());
  e.planner = next(spec_.planners.size());
  e.world = next(world_names_.size());
  e.id = world_names_[e.world] + "|" + spec_.planners[e.planner] + "|" +
         spec_.controllers[e.controller].name + "|" + spec_.faults[e.fault].name + "|" +
         std::to_string(e.seed);
  return e;
}

std::optional<std::int64_t> EpisodeSpace::find(const std::string& id) const {
  // Names never hold '|' (worlds/names.h): an id splits into exactly five parts.
  std::array<std::string, 5> parts;
  std::size_t begin = 0;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const std::size_t end = k + 1 < parts.size() ? id.find('|', begin) : id.size();
    if (end == std::string::npos) return std::nullopt;
    parts[k] = id.substr(begin, end - begin);
    begin = end + 1;
  }
  if (parts[4].find('|') != std::string::npos) return std::nullopt;
  const auto w = world_.find(parts[0]), p = planner_.find(parts[1]), c = controller_.find(parts[2]),
             f = fault_.find(parts[3]);
  if (w == world_.end() || p == planner_.end() || c == controller_.end() || f == fault_.end())
    return std::nullopt;
  std::uint64_t seed = 0;
  for (const char ch : parts[4]) {
    if (ch < '0' || ch > '9' || seed > (UINT64_MAX - 9) / 10) return std::nullopt;
    seed = seed * 10 + static_cast<std::uint64_t>(ch - '0');
  }
  const auto s = seed_.find(seed);
  if (s == seed_.end() || std::to_string(seed) != parts[4]) return std::nullopt;
  const auto n = [](std::size_t k) { return static_cast<std::int64_t>(k); };
  return (((n(w->second) * n(spec_.planners.size()) + n(p->second)) * n(spec_.controllers.size()) +
           n(c->second)) *
              n(spec_.faults.size()) +
          n(f->second)) *
             n(spec_.seeds.size()) +
         n(s->second);
}

std::int64_t EpisodeSpace::shard_size(int i, int n) const {
  return i < size_ % n ? size_ / n + 1 : size_ / n;
}

std::vector<Episode> EpisodeSpace::shard(int i, int n) const {
  const std::int64_t mine = shard_size(i, n);
  if (mine > kMaxEpisodes)
    throw std::invalid_argument(
        "one run makes at most " + std::to_string(kMaxEpisodes) + " episodes; this " +
        (n > 1 ? "shard" : "scenario") + " makes " + std::to_string(mine) + " of " +
        std::to_string(size_) + ": run it in shards (--shard i/n with n >= " +
        std::to_string((size_ + kMaxEpisodes - 1) / kMaxEpisodes) + ", docs/batch.md)");
  std::vector<Episode> out;
  out.reserve(static_cast<std::size_t>(mine));
  for (std::int64_t index = i; index < size_; index += n) out.push_back(at(index));
  return out;
}

}  // namespace plantsim::batch
