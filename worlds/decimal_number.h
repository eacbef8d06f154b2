// The one rule by which plantsim reads a number written as text in a YAML input (scenario,
// tuning section, ROS map YAML, Nav2 parameters) or in a tuning bound on the command line:
// decimal only, as YAML 1.2's core schema and the command line's options read them, so `010`
// is ten everywhere. yaml-cpp's own conversions differ: as<int>() reads a leading 0 as octal
// (`budget: 010` was 8 while `--budget 010` is 10) and 0x as hexadecimal, as<double>() takes
// `.inf` and `.nan`; none of them is used on input.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <optional>
#include <string>

namespace plantsim::worlds {

/// `[-+]digits[.digits][(e|E)[-+]digits]`, with a digit before or after the point (`.5`, `5.`):
/// YAML 1.2's decimal float without its .inf and .nan.
bool is_decimal_number(const std::string& text);

/// The finite number `text` writes by that rule; none for anything else (`0x10`, `1_000`,
/// `.inf`, `1e999`, text).
std::optional<double> decimal_number(const std::string& text);

/// The whole number `text` writes as `[+]digits` (leading zeros allowed: `010` is 10) up to
/// 2^64 - 1; none for anything else (a sign, a point, an exponent, `0o10`, `0x10`).
std::optional<std::uint64_t> decimal_whole_number(const std::string& text);

/// The same read from a YAML scalar (a quoted one too, as yaml-cpp reads them); none for a
/// mapping, a sequence or a null.
std::optional<double> decimal_number(const YAML::Node& node);
std::optional<std::uint64_t> decimal_whole_number(const YAML::Node& node);

}  // namespace plantsim::worlds
