// Parameter values checked by kind and range; unknown keys refused with a suggestion.
#include "worlds/param_json.h"

#include <cmath>
#include <sstream>
#include <vector>

#include "worlds/known_keys.h"
#include "worlds/world_error.h"

namespace plantsim::worlds {

ParamDocument::ParamDocument(const nlohmann::json& doc, std::string source)
    : doc_(doc), source_(std::move(source)) {
  if (!doc_.is_object()) throw WorldError(source_, "", "expected a JSON object");
}

const nlohmann::json* ParamDocument::find(const std::string& section, const std::string& name) {
  known_.insert(section.empty() ? name : section + "." + name);
  const nlohmann::json* object = &doc_;
  if (!section.empty()) {
    const auto it = doc_.find(section);
    if (it == doc_.end()) return nullptr;
    if (!it->is_object()) throw WorldError(source_, section, "expected an object");
    object = &*it;
  }
  const auto it = object->find(name);
  return it == object->end() ? nullptr : &*it;
}

double ParamDocument::checked(const nlohmann::json& v, const std::string& path,
                              util::ParamKind kind, double lo, double hi, bool above) const {
  if (kind == util::ParamKind::kFlag) {
    if (!v.is_boolean()) throw WorldError(source_, path, "expected true or false");
    return v.get<bool>() ? 1.0 : 0.0;
  }
  if (kind == util::ParamKind::kWhole) {
    // A count or a seed: a whole number in range, however JSON writes it (2, 2.0, 1e5).
    const bool whole =
        v.is_number_integer() || (v.is_number_float() && std::isfinite(v.get<double>()) &&
                                  v.get<double>() == std::floor(v.get<double>()));
    const double d = whole ? v.get<double>() : 0.0;
    if (!whole || d < lo || d > hi)
      throw WorldError(source_, path,
                       "expected a whole number from " +
                           std::to_string(static_cast<long long>(lo)) + " to " +
                           std::to_string(static_cast<long long>(hi)));
    return d;
  }
  if (!v.is_number()) throw WorldError(source_, path, "expected a number");
  const double d = v.get<double>();
  if (!std::isfinite(d)) throw WorldError(source_, path, "must be finite");
  if (d < lo || d > hi || (above && d <= lo)) {
    std::ostringstream range;
    range << "must be " << (above ? "above " : "at least ") << lo << " and at most " << hi;
    throw WorldError(source_, path, range.str());
  }
  return d;
}

void ParamDocument::refuse_choice(const std::string& path, const std::string& options) const {
  throw WorldError(source_, path, "expected " + options);
}

void ParamDocument::refuse_unknown() const {
  const std::vector<std::string> known(known_.begin(), known_.end());
  auto refuse = [&](const std::string& key) {
    const std::string near = nearest_known_name(key, known);
    throw WorldError(
        source_, key,
        near.empty() ? "unknown parameter" : "unknown parameter, did you mean '" + near + "'?");
  };
  for (const auto& [key, value] : doc_.items()) {
    if (known_.count(key) || key == "comment") continue;
    const std::string prefix = key + ".";
    const auto section = known_.lower_bound(prefix);
    if (!value.is_object() || section == known_.end() || section->rfind(prefix, 0) != 0)
      refuse(key);  // neither a key nor a section (an empty object included)
    for (const auto& [sub, _] : value.items())
      if (!known_.count(prefix + sub)) refuse(prefix + sub);
  }
}

}  // namespace plantsim::worlds
