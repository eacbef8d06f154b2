// Numbers written and read as the files define them ('.' decimals), whatever the process's C
// locale: printf and strtod follow LC_NUMERIC, which a host program may set (Python's
// locale.setlocale(LC_ALL, "de_DE.UTF-8") made trajectory.csv and summary.csv write "0,5" and
// the batch read them back wrong). iostreams follow the C++ global locale instead, which
// setlocale leaves alone, so ostringstream output needs nothing.
#pragma once

#include <cstddef>
#include <string>

namespace plantsim::util {

/// std::snprintf in the "C" locale (the calling thread's locale switched for the call only).
int c_snprintf(char* out, std::size_t size, const char* format, ...)
    __attribute__((format(printf, 3, 4)));

/// `v` as printf's "%g" writes it in the "C" locale (at most six significant digits): numbers in
/// messages and labels.
std::string c_general(double v);

/// std::strtod in the "C" locale.
double c_strtod(const char* text, char** end);

}  // namespace plantsim::util
