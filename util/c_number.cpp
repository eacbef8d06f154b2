// printf and strtod in the "C" locale (see the header). uselocale switches the calling thread
// only (POSIX), so other threads, and the host's own formatting, keep theirs.
#include "util/c_number.h"

#include <locale.h>

#include <cstdarg>
#include <cstdio>
#include <cstdlib>

namespace plantsim::util {
namespace {

locale_t c_locale() {
  // Made once and never freed: the process's threads may use it until exit.
  static const locale_t c = newlocale(LC_ALL_MASK, "C", static_cast<locale_t>(nullptr));
  return c;
}

/// The calling thread in the "C" locale for its lifetime.
class InCLocale {
 public:
  InCLocale() : was_(uselocale(c_locale())) {}
  ~InCLocale() { uselocale(was_); }
  InCLocale(const InCLocale&) = delete;
  InCLocale& operator=(const InCLocale&) = delete;

 private:
  locale_t was_;
};

}  // namespace

int c_snprintf(char* out, std::size_t size, const char* format, ...) {
  const InCLocale c;
  va_list args;
  va_start(args, format);
  const int n = std::vsnprintf(out, size, format, args);
  va_end(args);
  return n;
}

double c_strtod(const char* text, char** end) { return strtod_l(text, end, c_locale()); }

std::string c_general(double v) {
  char text[64];
  c_snprintf(text, sizeof text, "%g", v);
  return text;
}

}  // namespace plantsim::util
