#pragma once

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace rad::fuzz {

// The loaders read files by name, so each input is written to a private directory first
// (one per process: libFuzzer's -jobs/-workers run several side by side).
inline const std::filesystem::path& tempDir() {
  static const std::filesystem::path dir = [] {
    std::filesystem::path d =
        std::filesystem::temp_directory_path() / ("radiosity_fuzz_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(tempDir(), ec);
    });
    return d;
  }();
  return dir;
}

inline std::string writeTemp(const std::string& name, const char* data, std::size_t size) {
  const std::filesystem::path path = tempDir() / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(data, static_cast<std::streamsize>(size));
  return path.string();
}

}  // namespace rad::fuzz
