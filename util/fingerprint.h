// A 64-bit content fingerprint (FNV-1a): which world, which scenario. Not cryptographic; it
// tells apart inputs a user could confuse, and is the same on every machine and run.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace plantsim::util {

class Fingerprint {
 public:
  Fingerprint& add(std::string_view bytes) {
    for (unsigned char c : bytes) hash_ = (hash_ ^ c) * 0x100000001b3ULL;
    return add_length(bytes.size());
  }
  Fingerprint& add(double v) {
    if (v == 0.0) v = 0.0;  // -0 and 0 are the same position
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    return add_word(bits);
  }
  Fingerprint& add(std::uint64_t v) { return add_word(v); }
  std::uint64_t value() const { return hash_; }
  std::string hex() const {
    static const char* digits = "0123456789abcdef";
    std::string s(16, '0');
    for (int i = 0; i < 16; ++i) s[15 - i] = digits[(hash_ >> (4 * i)) & 0xf];
    return s;
  }

 private:
  Fingerprint& add_word(std::uint64_t v) {
    for (int i = 0; i < 8; ++i) hash_ = (hash_ ^ ((v >> (8 * i)) & 0xff)) * 0x100000001b3ULL;
    return *this;
  }
  // Length-prefixing keeps ("ab","c") apart from ("a","bc").
  Fingerprint& add_length(std::size_t n) { return add_word(static_cast<std::uint64_t>(n)); }
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

}  // namespace plantsim::util
