// PGM parsing by hand (a few lines of header); PNG handed to worlds/map_image_png.h.
#include "worlds/map_image.h"

#include <cctype>
#include <sstream>

#include "util/input_file.h"
#include "worlds/map_image_png.h"
#include "worlds/world_error.h"

namespace plantsim::worlds {
namespace {

// Skips white space and '#' comments between PGM header fields.
void skip_space(std::istream& in) {
  for (;;) {
    const int c = in.peek();
    if (c == '#') {
      std::string line;
      std::getline(in, line);
    } else if (c != EOF && std::isspace(c)) {
      in.get();
    } else {
      return;
    }
  }
}

MapImage decode_pgm(const std::string& bytes, const std::string& path) {
  std::istringstream in(bytes);
  std::string magic;
  in >> magic;
  MapImage p;
  skip_space(in);
  in >> p.width;
  skip_space(in);
  in >> p.height;
  skip_space(in);
  in >> p.max_value;
  if (!in || p.width <= 0 || p.height <= 0 || p.max_value <= 0 || p.max_value > 65535)
    throw WorldError(path, "header", "bad width, height or maximum value");
  if (static_cast<double>(p.width) * p.height > kMaxMapPixels)
    throw WorldError(path, "header", "image too large (over 64 Mpixel)");
  const std::size_t count = static_cast<std::size_t>(p.width) * p.height;
  if (magic == "P5") {
    in.get();  // the single white-space byte after the header
    const std::size_t bytes_per = p.max_value > 255 ? 2 : 1;
    const std::size_t start = static_cast<std::size_t>(in.tellg());
    if (bytes.size() < start || bytes.size() - start < count * bytes_per)
      throw WorldError(path, "pixels", "file ends before the last pixel");
    p.values.resize(count);
    const auto* raw = reinterpret_cast<const unsigned char*>(bytes.data() + start);
    for (std::size_t i = 0; i < count; ++i) {
      p.values[i] = bytes_per == 1 ? raw[i] : (raw[2 * i] << 8) | raw[2 * i + 1];
      // Above the header's maximum a sample has no shade (read as one, it came out free).
      if (p.values[i] > static_cast<std::uint32_t>(p.max_value))
        throw WorldError(path, "pixels", "a value is out of range (above the maximum)");
    }
  } else {
    // Text pixels take at least two bytes each: a header claiming more cannot be honest.
    if (count > bytes.size()) throw WorldError(path, "pixels", "file ends before the last pixel");
    p.values.resize(count);
    for (std::uint32_t& v : p.values) {
      long value = -1;
      if (!(in >> value) || value < 0 || value > p.max_value)
        throw WorldError(path, "pixels",
                         "file ends before the last pixel or a value is out of range");
      v = static_cast<std::uint32_t>(value);
    }
  }
  return p;
}

}  // namespace

MapImage read_map_image(const std::string& path) {
  std::string bytes;
  try {
    bytes = util::read_input_file(path);
  } catch (const util::InputFileError& e) {
    throw WorldError(
        path, "",
        std::string(e.what()) + " (the YAML's 'image' must name a readable PGM or PNG file)");
  }
  if (bytes.rfind("P5", 0) == 0 || bytes.rfind("P2", 0) == 0) return decode_pgm(bytes, path);
  if (bytes.rfind("\x89PNG", 0) == 0) return decode_png_map(bytes, path);
  throw WorldError(path, "magic", "not a PGM (P5, P2) or PNG image");
}

}  // namespace plantsim::worlds
