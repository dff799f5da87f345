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
  // Flushes, closes and checks for I/O errors (throws RuntimeFailure). Call finish() on every
  // file of a set before commit() on any, so a set is either all renamed into place or not at all.
  void finish();
  // finish() if not done yet, then renames into place.
  void commit();

 private:
  std::string path_, tempPath_;
  std::ofstream out_;
  bool finished_ = false;
  bool committed_ = false;
};

class AtomicPath;

// Commits a set of files together: finishes all, checks that each destination can take its name,
// then renames them; if a rename still fails, the files already renamed are removed again, so a
// failed set leaves none of its files behind. `written` are files a library wrote by name (the
// EXR pages) that belong to the same set.
void commitAll(const std::vector<AtomicFile*>& files, const std::vector<AtomicPath*>& written = {});

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
// Returns true when it did not exist before (so a failed run can remove it again).
bool ensureDirectory(const std::string& dir);

}  // namespace rad
