// A component's parameters as plain values, the form a registered component (built in or loaded
// from a plugin) declares them in and is built from: each ParamSpec names its section and key,
// its kind, default and closed range; ParamValues holds the values chosen for one episode, keyed
// "section.name". Header-only and free of plantsim's internals: installed for plugins.
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace plantsim::util {

enum class ParamKind { kReal, kWhole, kFlag };

struct ParamSpec {
  std::string section;  ///< the component's section in a configuration ("mppi")
  std::string name;     ///< the key in it ("temperature")
  ParamKind kind = ParamKind::kReal;
  double default_value = 0;
  double lo = 0, hi = 0;  ///< valid values: [lo, hi] (or (lo, hi] when `above`)
  bool above = false;
  std::string doc;  ///< one line for `plantsim info`: what it does, with its unit
  std::string path() const { return section.empty() ? name : section + "." + name; }
};

/// Values by "section.name" as configurations carry them: a flat list (a std::map member in the
/// episode's configuration trips GCC 12's maybe-uninitialized at every temporary).
using NamedValues = std::vector<std::pair<std::string, double>>;

/// The value of `path` in `values`, or null.
inline const double* find_value(const NamedValues& values, const std::string& path) {
  for (const auto& [name, v] : values)
    if (name == path) return &v;
  return nullptr;
}
/// Sets `path` in `values`.
inline void set_value(NamedValues& values, const std::string& path, double v) {
  for (auto& [name, have] : values)
    if (name == path) {
      have = v;
      return;
    }
  values.emplace_back(path, v);
}

/// The values of a component's parameters for one episode, by "section.name".
class ParamValues {
 public:
  ParamValues() = default;
  explicit ParamValues(const NamedValues& values) : values_(values.begin(), values.end()) {}

  /// The value of `path`; throws std::out_of_range naming it when the component never declared it.
  double real(const std::string& path) const {
    const auto it = values_.find(path);
    if (it == values_.end()) throw std::out_of_range("no parameter \"" + path + "\"");
    return it->second;
  }
  long long whole(const std::string& path) const { return static_cast<long long>(real(path)); }
  bool flag(const std::string& path) const { return real(path) != 0; }
  bool has(const std::string& path) const { return values_.count(path) != 0; }
  void set(const std::string& path, double v) { values_[path] = v; }
  const std::map<std::string, double>& all() const { return values_; }
  NamedValues named() const { return {values_.begin(), values_.end()}; }

 private:
  std::map<std::string, double> values_;
};

/// Each spec's default, as the values a component gets when nothing is configured.
inline ParamValues defaults_of(const std::vector<ParamSpec>& specs) {
  ParamValues v;
  for (const ParamSpec& s : specs) v.set(s.path(), s.default_value);
  return v;
}

}  // namespace plantsim::util
