// Numbers written and read in the "C" locale whatever the process's C locale is (issue 85): a
// Python host with locale.setlocale(LC_ALL, "de_DE.UTF-8") made snprintf write "0,5" into
// trajectory.csv and strtod read "0.5" as 0. Skipped where no comma-decimal locale is installed.
#include <gtest/gtest.h>

#include <clocale>
#include <cstdio>
#include <string>

#include "util/c_number.h"
#include "util/csv.h"
#include "util/fixed_text.h"

namespace plantsim::util {
namespace {

/// Switches the process's C locale to one with a decimal comma for the test's lifetime.
class CommaLocale {
 public:
  CommaLocale() : was_(std::setlocale(LC_ALL, nullptr)) {
    for (const char* name : {"de_DE.UTF-8", "de_DE.utf8", "fr_FR.UTF-8", "de_DE"})
      if (std::setlocale(LC_ALL, name)) {
        active_ = true;
        break;
      }
  }
  ~CommaLocale() { std::setlocale(LC_ALL, was_.c_str()); }
  bool active() const { return active_; }

 private:
  std::string was_;
  bool active_ = false;
};

TEST(CNumber, WritesAndReadsPointDecimalsUnderACommaLocale) {
  const CommaLocale comma;
  if (!comma.active()) GTEST_SKIP() << "no comma-decimal locale installed (de_DE.UTF-8)";
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", 0.5);
  ASSERT_EQ(std::string(text), "0,50") << "the locale should write a comma: the test tests nothing";
  c_snprintf(text, sizeof text, "%.2f;%g", 0.5, 1.25);
  EXPECT_EQ(std::string(text), "0.50;1.25");
  EXPECT_EQ(fixed(2.125, 2), "2.12");
  char* end = nullptr;
  const char* half = "0.5,1";
  EXPECT_EQ(c_strtod(half, &end), 0.5);
  EXPECT_EQ(end, half + 3);
  // A negative number is still a number, not a formula to quote, in a comma locale too.
  EXPECT_EQ(csv_field("-0.25"), "-0.25");
  // The caller's own formatting keeps its locale.
  std::snprintf(text, sizeof text, "%.1f", 1.5);
  EXPECT_EQ(std::string(text), "1,5");
}

}  // namespace
}  // namespace plantsim::util
