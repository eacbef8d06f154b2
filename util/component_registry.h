// One registry per extension point, each owned by the module that owns the interface
// (robot/estimator_registry.h, controller/local_controller_registry.h): entries by name, in the
// order they were added (the built-ins first, then each plugin's), never removed, so a reference
// to an entry stays valid for the process. A name is taken once; a second entry of the same name
// is refused naming both origins.
#pragma once

#include <deque>
#include <mutex>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace plantsim::util {

/// A name a registry refuses (malformed, or taken).
class RegistryError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// True for a name configurations can spell: 1 to 48 of a-z, 0-9, '-' and '_', starting with a
/// letter.
inline bool component_name_ok(std::string_view name) {
  if (name.empty() || name.size() > 48 || !(name[0] >= 'a' && name[0] <= 'z')) return false;
  for (char c : name)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_')) return false;
  return true;
}

template <typename Entry>
class ComponentRegistry {
 public:
  /// `kind` as messages name it ("local controller").
  explicit ComponentRegistry(std::string kind) : kind_(std::move(kind)) {}

  /// Adds `e` from `origin` ("built-in" or a plugin's file).
  void add(Entry e, const std::string& origin) {
    if (!component_name_ok(e.name))
      throw RegistryError(kind_ + " name \"" + e.name +
                          "\" is not a name configurations can spell (a-z, 0-9, '-', '_', "
                          "starting with a letter, at most 48)");
    if (!e.make) throw RegistryError(kind_ + " \"" + e.name + "\" has no factory");
    std::lock_guard<std::mutex> lock(mutex_);
    for (const Entry& have : entries_)
      if (have.name == e.name)
        throw RegistryError(kind_ + " \"" + e.name + "\" from " + origin +
                            " clashes with the one from " + have.origin);
    e.origin = origin;
    entries_.push_back(std::move(e));
  }

  /// The entry named `name`, or null.
  const Entry* find(std::string_view name) const {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const Entry& e : entries_)
      if (e.name == name) return &e;
    return nullptr;
  }

  /// The entry named `name`; throws RegistryError listing the known names.
  const Entry& at(std::string_view name) const {
    if (const Entry* e = find(name)) return *e;
    std::string known;
    for (const std::string& n : names()) known += (known.empty() ? "\"" : ", \"") + n + "\"";
    throw RegistryError("unknown " + kind_ + " \"" + std::string(name) + "\" (known: " + known +
                        ")");
  }

  std::vector<std::string> names() const {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::string> out;
    for (const Entry& e : entries_) out.push_back(e.name);
    return out;
  }

  /// Every entry, in the order added (a copy of the references, safe while plugins load).
  std::vector<const Entry*> entries() const {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<const Entry*> out;
    for (const Entry& e : entries_) out.push_back(&e);
    return out;
  }

  const std::string& kind() const { return kind_; }

 private:
  std::string kind_;
  mutable std::mutex mutex_;
  std::deque<Entry> entries_;  // a deque: references stay valid as entries are added
};

}  // namespace plantsim::util
