// RFC 4180 CSV fields: quoting a field for writing and splitting a line for reading.
#pragma once

#include <string>
#include <vector>

namespace plantsim::util {

/// The field as written: quoted when it holds a comma, a quote or a line break; text a
/// spreadsheet would take for a formula (starting with = + - @, a tab or a carriage return, and
/// not a number) written with a leading ' so that it is shown, never run.
std::string csv_field(const std::string& s);

/// The fields of one line (no line breaks inside quoted fields expected).
std::vector<std::string> csv_split(const std::string& line);

}  // namespace plantsim::util
