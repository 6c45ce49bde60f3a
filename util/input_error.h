#pragma once
// Bad external input (files, fields, arguments) is reported by throwing
// InputError once, at the edge where it is read; the CLI's main() catches it
// and prints what() as one line. Degenerate geometry is never an InputError.
#include <stdexcept>
#include <string>

namespace umbra::util {

class InputError : public std::runtime_error {
 public:
  /// `where` names the file and, when known, the line or JSON field
  /// ("scene.json: models[1].mesh", "box.off:12"); `what` says what is wrong.
  InputError(const std::string& where, const std::string& what)
      : std::runtime_error(where + ": " + what) {}
};

}  // namespace umbra::util
