// A component loaded from a plugin that threw: the exception the guards around plugins' parts
// (plugins/guarded_components.h) turn any exception into, so that the episode ends with the
// `plugin_error` reason instead of the program; the message names the plugin's file, the
// component and what it said.
#pragma once

#include <exception>
#include <stdexcept>
#include <string>

namespace plantsim::util {

class ComponentFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Inside a catch: rethrows the exception being handled as a ComponentFailure naming `who`.
[[noreturn, gnu::cold, gnu::noinline]] inline void rethrow_as_component_failure(
    const std::string& who) {
  try {
    throw;
  } catch (const ComponentFailure&) {
    throw;
  } catch (const std::exception& e) {
    throw ComponentFailure(who + " threw: " + e.what());
  } catch (...) {
    throw ComponentFailure(who + " threw something that is not a std::exception");
  }
}

}  // namespace plantsim::util
