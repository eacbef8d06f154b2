// The one error type of world loading: names the file and the field at fault, so a user can
// fix the input without reading code. Callers map it to exit code 2 (bad input).
#pragma once

#include <stdexcept>
#include <string>

namespace plantsim::worlds {

class WorldError : public std::runtime_error {
 public:
  WorldError(const std::string& file, const std::string& field, const std::string& problem)
      : std::runtime_error(file + ": " + (field.empty() ? "" : "field '" + field + "': ") +
                           problem),
        file_(file),
        field_(field) {}
  const std::string& file() const { return file_; }
  const std::string& field() const { return field_; }

 private:
  std::string file_;
  std::string field_;
};

}  // namespace plantsim::worlds
