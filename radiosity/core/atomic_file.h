#pragma once

#include <fstream>
#include <string>
#include <vector>

namespace rad {

// Writes a file under a temporary name next to its destination; commit() renames it into place.
// Destroyed without commit (an exception, a failed run), the temporary file is removed, so a
// reader never sees a half-written output.
class AtomicFile {
 public:
  explicit AtomicFile(std::string path, bool binary = false);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return out_; }
  const std::string& path() const { return path_; }
  // Flushes, checks for I/O errors and renames into place. Throws RuntimeFailure on failure.
  void commit();

 private:
  std::string path_, tempPath_;
  std::ofstream out_;
  bool committed_ = false;
};

// For libraries that write a file by name (OpenEXR): hands out a temporary path next to the
// destination; commit() renames it into place, destruction without commit removes it.
class AtomicPath {
 public:
  explicit AtomicPath(std::string path);
  ~AtomicPath();
  AtomicPath(const AtomicPath&) = delete;
  AtomicPath& operator=(const AtomicPath&) = delete;

  const std::string& tempPath() const { return tempPath_; }
  const std::string& path() const { return path_; }
  void commit();

 private:
  std::string path_, tempPath_;
  bool committed_ = false;
};

// Creates a directory (and parents) for outputs; throws InputError naming it if that fails.
void ensureDirectory(const std::string& dir);

}  // namespace rad
