#pragma once

#include <stdexcept>
#include <string>

namespace rad {

// Bad user input (scene files, options). Carries the file and line it refers to, so the message a
// user sees reads "path:line: what is wrong". The command line turns it into a non-zero exit.
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, int line, const std::string& what)
      : std::runtime_error(format(file, line, what)), file_(file), line_(line) {}
  explicit InputError(const std::string& what) : std::runtime_error(what), line_(0) {}

  const std::string& file() const { return file_; }
  int line() const { return line_; }

 private:
  static std::string format(const std::string& file, int line, const std::string& what) {
    if (file.empty()) return what;
    if (line <= 0) return file + ": " + what;
    return file + ":" + std::to_string(line) + ": " + what;
  }
  std::string file_;
  int line_;
};

// A failure of a library underneath (Embree device errors, I/O) that is not the user's input.
class RuntimeFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace rad
