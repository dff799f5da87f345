#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace rad::fuzz {

// The loaders read files by name, so each input is written to a private directory first
// (one per process: libFuzzer's -jobs/-workers run several side by side), removed when the
// process exits. (An std::atexit handler registered while the path was being made ran after the
// path's destructor, found it empty and removed nothing: 212 directories were left in /tmp.)
struct FuzzTempDir {
  std::filesystem::path path;
  FuzzTempDir()
      : path(std::filesystem::temp_directory_path() /
             ("radiosity_fuzz_" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path);
  }
  ~FuzzTempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  FuzzTempDir(const FuzzTempDir&) = delete;
  FuzzTempDir& operator=(const FuzzTempDir&) = delete;
};

inline const std::filesystem::path& tempDir() {
  static const FuzzTempDir dir;
  return dir.path;
}

inline std::string writeTemp(const std::string& name, const char* data, std::size_t size) {
  const std::filesystem::path path = tempDir() / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(data, static_cast<std::streamsize>(size));
  return path.string();
}

}  // namespace rad::fuzz
