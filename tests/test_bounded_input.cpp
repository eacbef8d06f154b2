// The JSON and YAML loaders bounded while they read (issue 85): nesting depth, nodes with
// aliases expanded, a second document, tags. Each refusal names the file and the field.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "scratch_folder.h"
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

class BoundedYaml : public test::ScratchFolder {
 protected:
  std::string load(const std::string& name, const std::string& text) {
    return refusal([&] { load_yaml_input(write(name, text)); });
  }
};

// YAML::Load built the whole tree before the nodes were counted: 8 MB took 1.9 GB.
TEST_F(BoundedYaml, EightMegabytesOfNodesAreRefusedWhileReadNamingTheNodeInLittleMemory) {
  std::string flood = "worlds: [";
  flood.reserve(8u << 20);
  while (flood.size() < (8u << 20)) flood += "0,";
  flood += "0]\n";
  const std::string path = write("flood.yaml", flood);
  const double before = peak_rss_mib();
  const std::string message = refusal([&] { load_yaml_input(path); });
  EXPECT_EQ(message.find(path + ": field 'worlds[1999"), 0u) << message;
  EXPECT_NE(message.find("expands to more than 200000 YAML nodes"), std::string::npos) << message;
  EXPECT_NE(message.find("(line 1)"), std::string::npos) << message;
  EXPECT_LT(peak_rss_mib() - before, 256.0);  // the file, read once and parsed as a stream
}

TEST_F(BoundedYaml, AliasesCountAtEveryUseAndMayNotContainThemselves) {
  std::string bomb = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int k = 1; k < 10; ++k) {
    const std::string prev = "*a" + std::to_string(k - 1);
    bomb += "a" + std::to_string(k) + ": &a" + std::to_string(k) + " [" + prev;
    for (int i = 1; i < 10; ++i) bomb += ", " + prev;
    bomb += "]\n";
  }
  EXPECT_NE(load("bomb.yaml", bomb).find("expands to more than 200000 YAML nodes"),
            std::string::npos);
  // One long scalar at every use: few nodes, gigabytes for whoever copies them.
  std::string text = "big: &t " + std::string(1u << 20, 'x') + "\nuses: [";
  for (int i = 0; i < 20; ++i) text += "*t, ";
  EXPECT_NE(load("text.yaml", text + "*t]\n").find("bytes of YAML text"), std::string::npos);
  EXPECT_NE(load("cycle.yaml", "a: &x [1, *x]\n").find("field 'a[1]': an alias inside the node"),
            std::string::npos);
  EXPECT_EQ(load("ok.yaml", "a: &x {b: 1}\nc: *x\n"), "");
}

TEST_F(BoundedYaml, NestingBeyondTheLimitIsRefusedNamingWhere) {
  EXPECT_EQ(load("ok.yaml", nested(kMaxYamlDepth, "[", "]")), "");
  const std::string message = load("deep.yaml", "a: " + nested(100000, "[", "]"));
  EXPECT_NE(message.find("field 'a[0][0]"), std::string::npos) << message.substr(0, 200);
  EXPECT_NE(message.find("nests deeper than 64 levels"), std::string::npos)
      << message.substr(0, 200);
  // Through an alias: 40 levels used at a depth of 40.
  const std::string forty = nested(40, "[", "]");
  EXPECT_NE(load("alias.yaml", "a: &d " + forty + "\nb: " + nested(40, "[", "") + "*d" +
                                   nested(40, "", "]") + "\n")
                .find("nests deeper than 64"),
            std::string::npos);
}

// yaml-cpp read the first document and dropped the rest, and ignored tags: such a file does
// not mean what it says.
TEST_F(BoundedYaml, ASecondDocumentATagAndAKeyGivenTwiceAreRefusedWithTheirField) {
  const std::string second = load("two.yaml", "seeds: 1\n---\nseeds: 2\n");
  EXPECT_NE(second.find("holds a second YAML document"), std::string::npos) << second;
  EXPECT_NE(second.find("(line 2)"), std::string::npos) << second;
  EXPECT_NE(load("end.yaml", "seeds: 1\n...\nseeds: 2\n").find("second YAML document"),
            std::string::npos);
  EXPECT_EQ(load("str.yaml", "tune:\n  budget: !!str 010\n"),
            write("str.yaml", "tune:\n  budget: !!str 010\n") +
                ": field 'tune.budget': has the YAML tag '!!str': tags are not read, write the "
                "value plainly (line 2)");
  EXPECT_NE(
      load("local.yaml", "faults: !foo {a: {}}\n").find("field 'faults': has the YAML tag '!foo'"),
      std::string::npos);
  EXPECT_NE(
      load("twice.yaml", "a:\n  b: 1\n  b: 2\n").find("field 'a.b': given twice in one mapping"),
      std::string::npos);
  // Quoting is no tag, and a document marker before the only document is no second one.
  EXPECT_EQ(load("ok.yaml", "---\na: 'text'\nb: \"010\"\n"), "");
}

}  // namespace
}  // namespace plantsim::worlds
