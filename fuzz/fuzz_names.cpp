// libFuzzer harness: names and the command lines printed for pasting. Any bytes through the one
// naming rule (worlds/names.h); a name it accepts prints as itself and makes a file-safe name;
// any bytes quoted for the shell (util/shell_word.h, the re-run line) read back as themselves,
// and as a link (render::url_attribute) hold only URL-safe characters and decode to themselves.
#include <cstdlib>

#include "fuzz/fuzz_input.h"
#include "render/report.h"
#include "util/shell_word.h"
#include "util/unicode_text.h"
#include "worlds/known_keys.h"
#include "worlds/names.h"

namespace {

// The words of a line as a POSIX shell splits them when nothing is expanded: '...' and \x quote.
std::string one_word(const std::string& line) {
  std::string word;
  int words = 0;
  bool in_word = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '\'') {
      const std::size_t end = line.find('\'', i + 1);
      if (end == std::string::npos) std::abort();  // an unclosed quote: the line is broken
      word += line.substr(i + 1, end - i - 1), i = end, in_word = true;
    } else if (c == '\\' && i + 1 < line.size()) {
      word += line[++i], in_word = true;
    } else if (c == ' ' || c == '\t' || c == '\n') {
      words += in_word, in_word = false;
    } else if (std::string("\"$`;&|<>()*?[]#~!{}").find(c) != std::string::npos) {
      std::abort();  // a character the shell would act on, outside quotes
    } else {
      word += c, in_word = true;
    }
  }
  if (words + in_word != 1) std::abort();
  return word;
}

void check_name(const std::string& name) {
  if (!plantsim::worlds::name_problem(name).empty()) return;
  if (plantsim::util::printable(name) != name) std::abort();
  const std::string file = plantsim::worlds::file_name_component(name);
  if (file.empty() || file.size() > 100 || file.find('/') != std::string::npos || file[0] == '.')
    std::abort();
}

void check_link(const std::string& path) {
  const std::string url = plantsim::render::url_attribute(path);
  if (url.find_first_not_of(
          "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-._~/%") !=
      std::string::npos)
    std::abort();
  const std::vector<std::string> back =
      plantsim::render::referenced_files("<a href=\"" + url + "\">");
  if (back.size() != 1 || back[0] != path) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  check_name(bytes);
  if (!bytes.empty() && bytes.find('\0') == std::string::npos &&
      one_word(plantsim::util::shell_word(bytes)) != bytes)
    std::abort();
  check_link(bytes);
  return 0;
}
