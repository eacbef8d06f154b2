// The one way plantsim declares a table of parameters (the episode configuration, seed 004's
// coverage parameters): each entry names its JSON section and key, the member it reads and
// writes, and the closed range of valid values (open at the low end with PLANTSIM_PARAM_ABOVE).
// Whether a parameter is a real number, a whole number or a flag follows from the member's type.
// Readers and writers walk the table, so a parameter is declared once for both.
#pragma once

#include <functional>
#include <string>
#include <type_traits>
#include <utility>

namespace plantsim::util {

enum class ParamKind { kReal, kWhole, kFlag };

template <typename P>
struct Param {
  const char* section;  ///< "" for a top-level key
  const char* name;
  ParamKind kind;
  std::function<double(const P&)> get;
  std::function<void(P&, double)> set;
  double lo, hi;
  bool above = false;  ///< lo itself excluded
  /// "section.name", or "name" at the top level.
  std::string path() const {
    return section[0] ? std::string(section) + "." + name : std::string(name);
  }
};

/// What the macros make: an entry not yet tied to its parameter type (the member is reached by a
/// generic lambda), turned into a Param<P> by the table it is listed in.
template <typename Ref>
struct ParamEntry {
  const char* section;
  const char* name;
  Ref ref;
  double lo, hi;
  bool above;
  template <typename P>
  operator Param<P>() const {
    using T = std::remove_reference_t<decltype(ref(std::declval<P&>()))>;
    const ParamKind kind = std::is_same_v<T, bool> ? ParamKind::kFlag
                           : std::is_integral_v<T> ? ParamKind::kWhole
                                                   : ParamKind::kReal;
    const Ref r = ref;
    return Param<P>{section,
                    name,
                    kind,
                    [r](const P& p) { return static_cast<double>(r(const_cast<P&>(p))); },
                    [r](P& p, double v) { r(p) = static_cast<T>(v); },
                    lo,
                    hi,
                    above};
  }
};
template <typename Ref>
ParamEntry(const char*, const char*, Ref, double, double, bool) -> ParamEntry<Ref>;

}  // namespace plantsim::util

/// A parameter `section.name` held in `member` of the table's parameter type, valid in [lo, hi].
#define PLANTSIM_PARAM(section, member, name, lo, hi)         \
  ::plantsim::util::ParamEntry {                              \
    section, name, [](auto& p) -> auto& { return p.member; }  \
    , static_cast<double>(lo), static_cast<double>(hi), false \
  }
/// The same, valid in (lo, hi].
#define PLANTSIM_PARAM_ABOVE(section, member, name, lo, hi)  \
  ::plantsim::util::ParamEntry {                             \
    section, name, [](auto& p) -> auto& { return p.member; } \
    , static_cast<double>(lo), static_cast<double>(hi), true \
  }
