// A component loaded from a plugin that threw: the exception the guards around plugins' parts
// (plugins/guarded_components.h) turn any exception into, so that the episode ends with the
// `plugin_error` reason instead of the program; the message names the plugin's file, the
// component and what it said.
#pragma once

#include <stdexcept>
#include <string>

namespace plantsim::util {

class ComponentFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace plantsim::util
