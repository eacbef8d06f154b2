// Reading UTF-8 one code point at a time, and text made safe to print on a terminal: what a
// name or a path from the user's files may hold that a terminal would act on (escape
// sequences, direction changes) shown as escapes instead.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace plantsim::util {

/// The code point at `i` (advanced past it), or -1 for a byte that does not start a valid
/// UTF-8 sequence (then `i` moves by one byte). Overlong forms and surrogates are invalid.
std::int32_t next_code_point(const std::string& text, std::size_t& i);

/// True for the code points a name may not hold, invisible or acting on the text around them:
/// C0 and C1 controls, DEL, zero-width and direction marks and overrides (U+200B..U+200F,
/// U+202A..U+202E, U+2060..U+2069), the byte-order mark U+FEFF, U+FFF9..U+FFFB and the
/// noncharacters (U+FDD0..U+FDEF, U+xFFFE, U+xFFFF).
bool invisible_or_control(std::int32_t code_point);

/// `text` with every invalid byte and every code point `invisible_or_control` calls so written
/// as an escape (\x1b, \u202e); newlines kept when `keep_newlines`.
std::string printable(const std::string& text, bool keep_newlines = false);

}  // namespace plantsim::util
