// The one way plantsim declares a table of parameters (the episode configuration, seed 004's
// coverage parameters): each entry names its JSON section and key, the member it reads and
// writes, and the closed range of valid values (open at the low end with PLANTSIM_PARAM_ABOVE).
// Whether a parameter is a real number, a whole number or a flag follows from the member's type.
// One reader and writer walks the table (worlds/param_json.h), so a parameter is declared once
// for both. Each module
// declares the rows of its own parameter structs (sim/sim_param_rows.h, robot/robot_param_rows.h,
// controller/controller_param_rows.h); a table of a larger struct takes them over with
// rows_of_part, so no row is written twice.
#pragma once

#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "util/param_spec.h"

namespace plantsim::util {

/// No parameter is meaningful beyond this; a bound keeps 1e308 out of the physics (it would
/// turn forces non-finite) and out of step counts (a timeout of 1e308 never ends).
inline constexpr double kMaxParameter = 1e6;

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

template <typename P>
using ParamRows = std::vector<Param<P>>;

/// A part's rows as rows of the whole P that holds it: `part` reaches the part from the whole (a
/// generic lambda returning a reference, PLANTSIM_PART). Each row keeps its section, key and
/// bounds.
template <typename P, typename Part, typename Reach>
void append_rows_of_part(ParamRows<P>& whole, const ParamRows<Part>& rows, Reach part) {
  for (const Param<Part>& r : rows)
    whole.push_back(
        Param<P>{r.section, r.name, r.kind,
                 [get = r.get, part](const P& p) { return get(part(const_cast<P&>(p))); },
                 [set = r.set, part](P& p, double v) { set(part(p), v); }, r.lo, r.hi, r.above});
}

/// The rows as plain specs (util/param_spec.h), each default read from `defaults`: how a built-in
/// component whose parameters are a struct declares them to its registry.
template <typename P>
std::vector<ParamSpec> specs_of(const ParamRows<P>& rows, const P& defaults = P{}) {
  std::vector<ParamSpec> out;
  for (const Param<P>& r : rows)
    out.push_back({r.section, r.name, r.kind, r.get(defaults), r.lo, r.hi, r.above, ""});
  return out;
}

/// The struct the values describe: each row set from its value ("section.name"), the rest left at
/// `base`.
template <typename P>
P struct_of(const ParamRows<P>& rows, const ParamValues& values, P base = P{}) {
  for (const Param<P>& r : rows)
    if (values.has(r.path())) r.set(base, values.real(r.path()));
  return base;
}

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
/// The part `member` of a larger parameter struct, for append_rows_of_part.
#define PLANTSIM_PART(member) \
  [](auto& p) -> auto& { return p.member; }
