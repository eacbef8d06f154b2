// Parameters that name one of a few options (`perception.mode`: "sensors" or "oracle"),
// declared as param_table.h declares numbers: each row names its JSON section and key, the enum
// member it reads and writes, and every option spelt as the file writes it beside the value it
// stands for. The module that owns the enum declares the row; worlds/param_json.h reads and writes
// it, so a new option is one line beside the enum.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace plantsim::util {

template <typename P>
struct Choice {
  const char* section;  ///< "" for a top-level key
  const char* name;
  std::vector<std::pair<std::string, int>> options;  ///< spelling, enum value
  std::function<int(const P&)> get;
  std::function<void(P&, int)> set;
  std::string path() const {
    return section[0] ? std::string(section) + "." + name : std::string(name);
  }
  /// The options as a message lists them: "a" or "b"; "a", "b" or "c".
  std::string spelt() const {
    std::string out;
    for (std::size_t i = 0; i < options.size(); ++i)
      out += (i == 0                    ? ""
              : i + 1 == options.size() ? " or "
                                        : ", ") +
             ("\"" + options[i].first + "\"");
    return out;
  }
};

template <typename P>
using ChoiceRows = std::vector<Choice<P>>;

/// What PLANTSIM_CHOICE makes: a row not yet tied to its parameter type.
template <typename Ref, typename E>
struct ChoiceEntry {
  const char* section;
  const char* name;
  Ref ref;
  std::vector<std::pair<std::string, E>> options;
  template <typename P>
  operator Choice<P>() const {
    std::vector<std::pair<std::string, int>> spelt;
    for (const auto& [text, value] : options) spelt.emplace_back(text, static_cast<int>(value));
    const Ref r = ref;
    return Choice<P>{section, name, spelt,
                     [r](const P& p) { return static_cast<int>(r(const_cast<P&>(p))); },
                     [r](P& p, int v) { r(p) = static_cast<E>(v); }};
  }
};

template <typename E, typename Ref>
ChoiceEntry<Ref, E> make_choice(const char* section, const char* name, Ref ref,
                                std::vector<std::pair<std::string, E>> options) {
  return {section, name, ref, std::move(options)};
}

/// A part's choices as choices of the whole P that holds it (as append_rows_of_part).
template <typename P, typename Part, typename Reach>
void append_choices_of_part(ChoiceRows<P>& whole, const ChoiceRows<Part>& rows, Reach part) {
  for (const Choice<Part>& r : rows)
    whole.push_back(
        Choice<P>{r.section, r.name, r.options,
                  [get = r.get, part](const P& p) { return get(part(const_cast<P&>(p))); },
                  [set = r.set, part](P& p, int v) { set(part(p), v); }});
}

}  // namespace plantsim::util

/// A choice `section.name` held in the enum `member` (of type E), one of the listed
/// {"spelling", E::kValue} options.
#define PLANTSIM_CHOICE(section, member, name, E, ...)          \
  ::plantsim::util::make_choice<E>(                             \
      section, name, [](auto& p) -> auto& { return p.member; }, \
      std::vector<std::pair<std::string, E>>{__VA_ARGS__})
