// The loader and the registrar it hands a plugin.
#include "plugins/plugin_loader.h"

#include <dlfcn.h>

#include <deque>
#include <filesystem>
#include <mutex>
#include <set>

#include "controller/local_controller_registry.h"
#include "plugins/guarded_components.h"
#include "plugins/plugin_api.h"
#include "util/component_failure.h"
#include "util/component_registry.h"
#include "util/shell_word.h"

namespace plantsim::plugins {

namespace {

std::mutex& loader_mutex() {
  static std::mutex m;
  return m;
}
std::deque<LoadedPlugin>& loaded() {
  static auto* plugins = new std::deque<LoadedPlugin>;  // as long as the components it lists
  return *plugins;
}

/// The component's declared parameters, checked: sections and keys a configuration can spell,
/// defaults within their bounds, no key declared twice.
void check_params(const util::ComponentInfo& c, const std::string& who) {
  std::set<std::string> seen;
  for (const util::ParamSpec& s : c.params) {
    if (!util::component_name_ok(s.section) || !util::component_name_ok(s.name))
      throw PluginError(who + ": parameter \"" + s.path() +
                        "\" is not a section.key a configuration can spell (a-z, 0-9, '-', "
                        "'_', starting with a letter)");
    if (!seen.insert(s.path()).second)
      throw PluginError(who + ": parameter \"" + s.path() + "\" declared twice");
    if (!(s.lo <= s.hi) || !(s.default_value >= s.lo && s.default_value <= s.hi) ||
        (s.above && !(s.default_value > s.lo)))
      throw PluginError(who + ": parameter \"" + s.path() + "\" has a default outside its bounds");
  }
}

/// Collects a plugin's components; add() puts them into the registries once all are checked.
class CheckingRegistrar : public Registrar {
 public:
  explicit CheckingRegistrar(std::string file) : file_(std::move(file)) {}

  void add_local_controller(controller::LocalControllerEntry e) override {
    controllers_.push_back(std::move(e));
  }
  void add_estimator(robot::EstimatorEntry e) override { estimators_.push_back(std::move(e)); }
  void add_planner(planner::PlannerEntry e) override { planners_.push_back(std::move(e)); }
  void add_dock_detector(robot::DockDetectorEntry e) override {
    detectors_.push_back(std::move(e));
  }

  /// Checks every component, tries each factory with its defaults, then registers them all.
  void add(LoadedPlugin& record) {
    if (controllers_.empty() && estimators_.empty() && planners_.empty() && detectors_.empty())
      throw PluginError(file_ + ": the plugin registered no component");
    std::set<std::string> names;
    for (const auto& e : controllers_) check(e, controller::local_controllers(), names);
    for (const auto& e : estimators_) check(e, robot::estimators(), names);
    for (const auto& e : planners_) check(e, planner::planners(), names);
    for (const auto& e : detectors_) check(e, robot::dock_detectors(), names);
    for (auto& e : detectors_) {
      e = guarded(std::move(e), file_);
      robot::DockDetectorContext context;
      context.mapped_dock = {5, 5, 0};
      context.charger_width_m = 0.3;
      try_factory(e, context);
    }
    for (auto& e : planners_) {
      try_planner_factory(e);
      e = guarded(std::move(e), file_);
    }
    for (auto& e : controllers_) {
      e = guarded(std::move(e), file_);
      try_factory(e, controller::LocalControllerContext{});
    }
    for (auto& e : estimators_) {
      e = guarded(std::move(e), file_);
      robot::EstimatorContext context;
      context.floor = {0, 0, 10, 10};
      context.start = {1, 1, 0};
      try_factory(e, context);
    }
    for (auto& e : controllers_) {
      record.local_controllers.push_back(e.name);
      controller::local_controllers().add(std::move(e), file_);
    }
    for (auto& e : estimators_) {
      record.estimators.push_back(e.name);
      robot::estimators().add(std::move(e), file_);
    }
    for (auto& e : planners_) {
      record.planners.push_back(e.name);
      planner::planners().add(std::move(e), file_);
    }
    for (auto& e : detectors_) {
      record.dock_detectors.push_back(e.name);
      robot::dock_detectors().add(std::move(e), file_);
    }
  }

 private:
  template <typename Entry>
  void check(const Entry& e, const util::ComponentRegistry<Entry>& registry,
             std::set<std::string>& names) {
    const std::string& kind = registry.kind();
    const std::string who = file_ + ": " + kind + " \"" + e.name + "\"";
    if (!util::component_name_ok(e.name))
      throw PluginError(file_ + ": " + kind + " name \"" + e.name +
                        "\" is not a name a configuration can spell (a-z, 0-9, '-', '_', "
                        "starting with a letter, at most 48)");
    if (!e.make) throw PluginError(who + " has no factory");
    const Entry* have = registry.find(e.name);
    if (have || !names.insert(kind + e.name).second)
      throw PluginError(who + " clashes with the one from " +
                        (have ? have->origin : std::string("the same plugin")));
    check_params(e, who);
  }

  template <typename Entry, typename Context>
  void try_factory(const Entry& e, const Context& context) {
    try {
      e.make(context, util::defaults_of(e.params));
    } catch (const util::ComponentFailure& failure) {
      throw PluginError(file_ +
                        ": its factory failed with the default parameters: " + failure.what());
    }
  }

  /// A planner's factory on a small empty floor, before it is guarded (the guard turns a
  /// throwing factory into a planner that fails each episode, which loading must not hide).
  void try_planner_factory(const planner::PlannerEntry& e) {
    std::set<std::string> options;
    for (const planner::OptionSpec& o : e.options)
      if (!util::component_name_ok(o.name) || !options.insert(o.name).second ||
          !(o.min <= o.default_value && o.default_value <= o.max))
        throw PluginError(file_ + ": planner \"" + e.name + "\": option \"" + o.name +
                          "\" is unnamed, declared twice or has a default outside its bounds");
    planner::PlannerInput input;
    input.floor = {0, 0, 10, 10};
    try {
      if (!e.make(input)) throw std::runtime_error("it made nothing");
    } catch (const std::exception& x) {
      throw PluginError(file_ + ": planner \"" + e.name +
                        "\": its factory failed on an empty 10 x 10 m floor: " + x.what());
    } catch (...) {
      throw PluginError(file_ + ": planner \"" + e.name +
                        "\": its factory threw something that is not a std::exception");
    }
  }

  std::string file_;
  std::vector<controller::LocalControllerEntry> controllers_;
  std::vector<robot::EstimatorEntry> estimators_;
  std::vector<planner::PlannerEntry> planners_;
  std::vector<robot::DockDetectorEntry> detectors_;
};

}  // namespace

const LoadedPlugin& load_plugin(const std::string& path, bool from_command_line) {
  std::lock_guard<std::mutex> lock(loader_mutex());
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw PluginError(path + ": no such plugin file");
  const std::string canonical = std::filesystem::canonical(path, ec).string();
  for (LoadedPlugin& p : loaded())
    if (p.canonical == canonical) {
      p.from_command_line |= from_command_line;
      return p;
    }
  // A path without a slash would be searched for on the library path: load the file named.
  const std::string opened = std::filesystem::absolute(path).string();
  void* handle = dlopen(opened.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    throw PluginError(path + ": cannot be loaded: " + (why ? why : "unknown reason"));
  }
  using AbiFunction = int (*)();
  using RegisterFunction = void (*)(Registrar&);
  auto abi = reinterpret_cast<AbiFunction>(dlsym(handle, PLANTSIM_PLUGIN_ABI_SYMBOL));
  auto enter = reinterpret_cast<RegisterFunction>(dlsym(handle, PLANTSIM_PLUGIN_REGISTER_SYMBOL));
  // The library stays open even when refused: a static object of it may already be registered
  // with the C++ runtime, and closing it would leave that dangling.
  if (!abi)
    throw PluginError(path + ": not a plantsim plugin (no " PLANTSIM_PLUGIN_ABI_SYMBOL
                             " symbol; build it with PLANTSIM_PLUGIN from plugins/plugin_api.h)");
  if (abi() != PLANTSIM_PLUGIN_ABI_VERSION)
    throw PluginError(path + ": built for plugin ABI version " + std::to_string(abi()) +
                      ", this plantsim loads version " +
                      std::to_string(PLANTSIM_PLUGIN_ABI_VERSION) +
                      ": rebuild it against this plantsim's installed package");
  if (!enter) throw PluginError(path + ": no " PLANTSIM_PLUGIN_REGISTER_SYMBOL " symbol");
  CheckingRegistrar registrar(path);
  try {
    enter(registrar);
  } catch (const PluginError&) {
    throw;
  } catch (const std::exception& e) {
    throw PluginError(path + ": its registration threw: " + e.what());
  } catch (...) {
    throw PluginError(path + ": its registration threw");
  }
  LoadedPlugin record{path, from_command_line, canonical, {}, {}, {}, {}};
  registrar.add(record);
  loaded().push_back(std::move(record));
  return loaded().back();
}

std::string command_line_plugin_arguments() {
  std::string out;
  for (const LoadedPlugin& p : loaded_plugins())
    if (p.from_command_line) out += " --plugin " + util::shell_word(p.path);
  return out;
}

std::vector<LoadedPlugin> loaded_plugins() {
  std::lock_guard<std::mutex> lock(loader_mutex());
  return {loaded().begin(), loaded().end()};
}

}  // namespace plantsim::plugins
