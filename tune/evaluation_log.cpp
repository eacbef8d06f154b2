// Writing and reading evaluations.jsonl.
#include "tune/evaluation_log.h"

#include <fcntl.h>
#include <unistd.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "util/atomic_file.h"
#include "worlds/json_input.h"

namespace plantsim::tune {

namespace {

using nlohmann::json;

json line_json(const Evaluation& e, const std::vector<TunedParameter>& parameters,
               const std::string& fingerprint) {
  json j;
  j["tune"] = fingerprint;
  j["search"] = e.search;
  j["index"] = e.index;
  json values = json::object();
  for (std::size_t i = 0; i < parameters.size(); ++i) values[parameters[i].info.path] = e.values[i];
  j["values"] = values;
  j["problem"] = e.problem;
  j["score"] = e.score.value;
  j["feasible"] = e.score.feasible;
  j["episodes"] = e.stats.episodes;
  j["succeeded"] = e.stats.succeeded;
  j["wilson_low"] = e.stats.wilson_low;
  j["wilson_high"] = e.stats.wilson_high;
  j["mean_time_s"] = e.stats.mean_time_s ? json(*e.stats.mean_time_s) : json(nullptr);
  j["mean_position_error_m"] =
      e.stats.mean_position_error_m ? json(*e.stats.mean_position_error_m) : json(nullptr);
  j["contacts"] = e.stats.contacts;
  j["wall_s"] = e.wall_s;
  json episodes = json::array();
  for (const EpisodeOutcome& o : e.outcomes)
    episodes.push_back({o.id, o.succeeded, o.time_s, o.position_error_m, o.contacts});
  j["episode_outcomes"] = std::move(episodes);  // [id, docked, time_s, position_error_m, contacts]
  return j;
}

Evaluation from_json(const json& j, const std::vector<TunedParameter>& parameters) {
  Evaluation e;
  e.search = j.at("search").get<std::string>();
  e.index = j.at("index").get<int>();
  for (const TunedParameter& p : parameters)
    e.values.push_back(j.at("values").at(p.info.path).get<double>());
  e.problem = j.at("problem").get<std::string>();
  e.score.value = j.at("score").get<double>();
  e.score.feasible = j.at("feasible").get<bool>();
  e.wall_s = j.at("wall_s").get<double>();
  for (const json& o : j.at("episode_outcomes"))
    e.outcomes.push_back({o.at(0).get<std::string>(), o.at(1).get<bool>(), o.at(2).get<double>(),
                          o.at(3).get<double>(), o.at(4).get<int>()});
  e.stats = statistics(e.outcomes);
  return e;
}

}  // namespace

std::vector<Evaluation> read_evaluations(const std::string& path, const std::string& fingerprint,
                                         const std::vector<TunedParameter>& parameters,
                                         std::int64_t& cut, std::string* kept_text) {
  std::vector<Evaluation> out;
  std::ifstream in(path);
  if (!in) return out;
  std::stringstream all;
  all << in.rdbuf();
  const std::string text = all.str();
  std::size_t begin = 0;
  while (begin < text.size()) {
    const std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) {  // a line a kill cut short
      ++cut;
      break;
    }
    const std::string line = text.substr(begin, end - begin);
    begin = end + 1;
    try {
      const json j = worlds::parse_json_input(line, path);  // bounded; WorldError cuts it
      if (j.at("tune").get<std::string>() != fingerprint)
        throw std::invalid_argument(
            "'" + path + "' holds evaluations of another tuning (fingerprint " +
            j.at("tune").get<std::string>() + ", this one " + fingerprint +
            ": another scenario, parameter, bound, objective, budget, method or seed)");
      out.push_back(from_json(j, parameters));
      if (kept_text) *kept_text += line + "\n";
    } catch (const std::invalid_argument&) {
      throw;
    } catch (const std::exception&) {
      ++cut;
    }
  }
  return out;
}

EvaluationLog::EvaluationLog(const std::string& path, const std::string& fingerprint,
                             const std::vector<TunedParameter>& parameters)
    : path_(path), fingerprint_(fingerprint), parameters_(parameters) {
  std::int64_t cut = 0;
  std::string kept;
  std::vector<Evaluation> known;
  try {
    known = read_evaluations(path, fingerprint, parameters, cut, &kept);
  } catch (const std::invalid_argument& other) {
    throw std::invalid_argument(std::string(other.what()) +
                                "; choose another --out, or --fresh to discard them");
  }
  for (Evaluation& e : known) recorded_[{e.search, e.index}] = std::move(e);
  if (cut > 0) {
    util::write_file_atomically(path, kept);
    std::fprintf(stderr, "tune: warning: cut %lld unfinished or malformed line(s) from %s\n",
                 static_cast<long long>(cut), path.c_str());
  }
  const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
  out_ = fd >= 0 ? ::fdopen(fd, "ab") : nullptr;
  if (!out_) {
    if (fd >= 0) ::close(fd);
    throw std::invalid_argument(util::system_error_text("cannot append to " + path));
  }
}

EvaluationLog::~EvaluationLog() {
  if (out_) std::fclose(out_);
}

const Evaluation* EvaluationLog::find(const std::string& search, int index,
                                      const std::vector<double>& values) const {
  const auto it = recorded_.find({search, index});
  if (it == recorded_.end() || it->second.values != values) return nullptr;
  ++reused_;
  return &it->second;
}

void EvaluationLog::append(const Evaluation& e) {
  const std::string line = line_json(e, parameters_, fingerprint_).dump() + "\n";
  if (std::fwrite(line.data(), 1, line.size(), out_) != line.size() || std::fflush(out_) != 0)
    throw std::runtime_error(util::system_error_text("cannot append to " + path_));
  recorded_[{e.search, e.index}] = e;
}

bool EvaluationLog::adopt(const Evaluation& e) {
  if (recorded_.count({e.search, e.index})) return false;
  append(e);
  return true;
}

}  // namespace plantsim::tune
