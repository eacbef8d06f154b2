// Family options by name: given values, defaults, and the check against a family's declaration.
#include "planner/planner_options.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace plantsim::planner {

void check_options(std::string_view planner, const PlannerOptions& options,
                   const std::vector<OptionSpec>& specs) {
  for (const auto& given : options.given()) {
    // Not a structured binding: clang 14 (the sanitizer build's) cannot capture one.
    const std::string& name = given.first;
    const double value = given.second;
    const auto spec = std::find_if(specs.begin(), specs.end(),
                                   [&](const OptionSpec& s) { return s.name == name; });
    std::ostringstream why;
    why << "planner " << planner << ": ";
    if (spec == specs.end()) {
      why << "takes no option '" << name << "'";
      if (specs.empty()) why << " (it takes none)";
      for (std::size_t i = 0; i < specs.size(); ++i)
        why << (i == 0 ? " (it takes: " : ", ") << specs[i].name
            << (i + 1 == specs.size() ? ")" : "");
      throw std::invalid_argument(why.str());
    }
    const bool whole = !spec->integer || std::floor(value) == value;
    if (!std::isfinite(value) || value < spec->min || value > spec->max || !whole) {
      why << "option '" << name << "' (" << spec->meaning << ") must be "
          << (spec->integer ? "a whole number " : "") << "from " << spec->min << " to " << spec->max
          << ", not " << value;
      throw std::invalid_argument(why.str());
    }
  }
}

}  // namespace plantsim::planner
