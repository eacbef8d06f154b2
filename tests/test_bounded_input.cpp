// The JSON reader bounded while it reads (issue 85): nesting depth. Each refusal names the file
// and the field.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "worlds/json_input.h"
#include "worlds/world_error.h"
#include "worlds/yaml_input.h"

namespace plantsim::worlds {
namespace {

// The message a load throws ("" when it loads).
template <typename Load>
std::string refusal(Load&& load) {
  try {
    load();
  } catch (const WorldError& e) {
    return e.what();
  }
  return "";
}

// Peak resident memory of this process so far, in MiB (ru_maxrss is in KiB on Linux).
double peak_rss_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

std::string nested(std::size_t levels, const std::string& open, const std::string& close) {
  std::string s;
  s.reserve(levels * (open.size() + close.size()));
  for (std::size_t i = 0; i < levels; ++i) s += open;
  for (std::size_t i = 0; i < levels; ++i) s += close;
  return s;
}

// Each level kept its whole path: 60 KB of brackets took 1.7 GB, 120 KB ended in bad_alloc.
TEST(BoundedJson, AMegabyteOfNestingIsRefusedAtTheLimitNamingWhereInLittleMemory) {
  const double before = peak_rss_mib();
  const std::string arrays = nested(512 * 1024, "[", "]");  // 1 MiB
  const std::string message = refusal([&] { parse_json_input(arrays, "deep.json"); });
  EXPECT_NE(message.find("deep.json: field '[0][0][0]"), std::string::npos)
      << message.substr(0, 200);
  EXPECT_NE(message.find("nests deeper than 64 levels"), std::string::npos)
      << message.substr(0, 200);
  const std::string objects = nested(100 * 1024, "{\"a\":", "}");
  const std::string in_objects = refusal([&] { parse_json_input(objects, "deep.json"); });
  std::string path = "a";
  for (int i = 1; i < kMaxJsonDepth; ++i) path += ".a";
  EXPECT_NE(in_objects.find("field '" + path + "': nests deeper"), std::string::npos)
      << in_objects.substr(0, 200);
  EXPECT_LT(peak_rss_mib() - before, 256.0);  // the inputs themselves are 1.5 MiB
}

TEST(BoundedJson, NestingUpToTheLimitLoadsAndKeysGivenTwiceAreNamedThroughArrays) {
  EXPECT_NO_THROW(parse_json_input(nested(kMaxJsonDepth, "[", "]"), "ok.json"));
  EXPECT_NE(refusal([] { parse_json_input(nested(kMaxJsonDepth + 1, "[", "]"), "x.json"); }), "");
  EXPECT_EQ(refusal([] { parse_json_input(R"([[0], [1, {"x": 1, "x": 2}]])", "k.json"); }),
            "k.json: field '[1][1].x': given twice in one object");
  EXPECT_EQ(refusal([] { parse_json_input(R"({"a": [{}, {"b": {"c": 1, "c": 1}}]})", "k.json"); }),
            "k.json: field 'a[1].b.c': given twice in one object");
  // The ordered reader (a file rewritten for the user keeps its order) is the same reader.
  const auto ordered = parse_ordered_json_input(R"({"z": 1, "a": 2})", "o.json");
  EXPECT_EQ(ordered.begin().key(), "z");
  EXPECT_NE(refusal([] { parse_ordered_json_input(nested(100, "[", "]"), "o.json"); }), "");
}

}  // namespace
}  // namespace plantsim::worlds
