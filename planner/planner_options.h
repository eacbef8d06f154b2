// Options of one planner family, by name: each family declares the ones it takes (name,
// default, bounds, meaning) in its own folder and reads them from here; the registry refuses a
// name the chosen family does not declare, or a value out of its bounds, before building. A new
// family's knob touches its own folder only, never the planner interface.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace plantsim::planner {

struct OptionSpec {
  std::string name;
  double default_value = 0;
  double min = 0;  ///< inclusive
  double max = 0;  ///< inclusive
  bool integer = false;
  std::string meaning;
};

class PlannerOptions {
 public:
  // Inline: a plugin's planner (installed header) reads its options without linking plantsim.
  PlannerOptions& set(const std::string& name, double value) {
    values_[name] = value;
    return *this;
  }
  /// The value given for `spec`, else its default.
  double get(const OptionSpec& spec) const {
    const auto it = values_.find(spec.name);
    return it == values_.end() ? spec.default_value : it->second;
  }
  int get_int(const OptionSpec& spec) const { return static_cast<int>(get(spec)); }
  const std::map<std::string, double>& given() const { return values_; }

 private:
  std::map<std::string, double> values_;
};

/// Throws std::invalid_argument naming the planner and the option when `options` holds a name
/// not in `specs`, or a value that is not finite, outside its bounds or not whole where it must be.
void check_options(std::string_view planner, const PlannerOptions& options,
                   const std::vector<OptionSpec>& specs);

}  // namespace plantsim::planner
