// The one JSON reader and writer of parameter tables (util/param_table.h), for the episode's
// configuration and seed 004's coverage parameters alike: each row's value checked by its kind
// (a real number, a whole number, a flag) and its range, every error naming the file and the
// field, and a key no row knows refused with the nearest known one suggested.
#pragma once

#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "util/choice_table.h"
#include "util/param_table.h"

namespace plantsim::worlds {

/// A parameter file's JSON object, its values looked up by section and name; a key no lookup
/// asked for is unknown.
class ParamDocument {
 public:
  /// Refuses anything but a JSON object.
  ParamDocument(const nlohmann::json& doc, std::string source);

  /// The value of `section.name` (`name` at the top level when `section` is empty), or none;
  /// the key is known from now on. A section that is not an object is refused.
  const nlohmann::json* find(const std::string& section, const std::string& name);

  /// Every row's value the document holds, checked and set in `out`.
  template <typename P>
  void read(const util::ParamRows<P>& rows, P& out) {
    for (const util::Param<P>& r : rows)
      if (const nlohmann::json* v = find(r.section, r.name))
        r.set(out, checked(*v, r.path(), r.kind, r.lo, r.hi, r.above));
  }

  /// Every choice the document holds, checked against its options and set in `out`.
  template <typename P>
  void read(const util::ChoiceRows<P>& rows, P& out) {
    for (const util::Choice<P>& r : rows)
      if (const nlohmann::json* v = find(r.section, r.name)) r.set(out, chosen(*v, r));
  }

  /// Refuses the first key no lookup asked for (a top-level "comment" is a note, not a key).
  void refuse_unknown() const;

  const std::string& source() const { return source_; }

 private:
  double checked(const nlohmann::json& v, const std::string& path, util::ParamKind kind, double lo,
                 double hi, bool above) const;

  template <typename P>
  int chosen(const nlohmann::json& v, const util::Choice<P>& r) const {
    if (v.is_string())
      for (const auto& [text, value] : r.options)
        if (v.get<std::string>() == text) return value;
    refuse_choice(r.path(), r.spelt());
  }
  [[noreturn]] void refuse_choice(const std::string& path, const std::string& options) const;

  const nlohmann::json& doc_;
  std::string source_;
  std::set<std::string> known_;
};

/// The rows' values in `out`, by section (top-level keys for rows without one), in the rows'
/// order.
template <typename P>
void write_param_rows(nlohmann::ordered_json& out, const util::ParamRows<P>& rows, const P& p) {
  for (const util::Param<P>& r : rows) {
    const double v = r.get(p);
    const nlohmann::ordered_json value =
        r.kind == util::ParamKind::kFlag    ? nlohmann::ordered_json(v != 0)
        : r.kind == util::ParamKind::kWhole ? nlohmann::ordered_json(static_cast<long long>(v))
                                            : nlohmann::ordered_json(v);
    if (r.section[0])
      out[r.section][r.name] = value;
    else
      out[r.name] = value;
  }
}

/// The choices' options as the file spells them.
template <typename P>
void write_param_rows(nlohmann::ordered_json& out, const util::ChoiceRows<P>& rows, const P& p) {
  for (const util::Choice<P>& r : rows) {
    const int chosen = r.get(p);
    for (const auto& [text, value] : r.options) {
      if (value != chosen) continue;
      if (r.section[0])
        out[r.section][r.name] = text;
      else
        out[r.name] = text;
    }
  }
}

}  // namespace plantsim::worlds
