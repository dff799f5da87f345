#include "radiosity/core/atomic_file.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <system_error>

#include "radiosity/core/errors.h"

namespace rad {

AtomicFile::AtomicFile(std::string path, bool binary)
    : path_(std::move(path)),
      tempPath_(path_ + ".tmp" + std::to_string(static_cast<long>(getpid()))) {
  out_.open(tempPath_, binary ? std::ios::out | std::ios::binary | std::ios::trunc
                              : std::ios::out | std::ios::trunc);
  if (!out_) throw RuntimeFailure("cannot write " + path_);
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::remove(tempPath_.c_str());
  }
}

void AtomicFile::finish() {
  if (finished_) return;
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok || out_.fail()) throw RuntimeFailure("error while writing " + path_);
  finished_ = true;
}

void AtomicFile::commit() {
  finish();
  std::error_code ec;
  std::filesystem::rename(tempPath_, path_, ec);
  if (ec) throw RuntimeFailure("cannot rename " + tempPath_ + " to " + path_ + ": " + ec.message());
  committed_ = true;
}

void commitAll(const std::vector<AtomicFile*>& files, const std::vector<AtomicPath*>& written) {
  for (AtomicFile* file : files) file->finish();
  std::vector<std::string> destinations;
  for (const AtomicFile* file : files) destinations.push_back(file->path());
  for (const AtomicPath* file : written) destinations.push_back(file->path());
  for (const std::string& path : destinations)
    if (std::filesystem::is_directory(path))
      throw RuntimeFailure("cannot write " + path + ": a directory is in the way");
  size_t committed = 0;
  try {
    for (; committed < destinations.size(); ++committed) {
      if (committed < files.size())
        files[committed]->commit();
      else
        written[committed - files.size()]->commit();
    }
  } catch (...) {
    for (size_t k = 0; k < committed; ++k) std::remove(destinations[k].c_str());
    throw;
  }
}

namespace {
std::string temporaryName(const std::string& path) {
  return path + ".tmp" + std::to_string(static_cast<long>(getpid()));
}
}  // namespace

AtomicPath::AtomicPath(std::string path)
    : path_(std::move(path)), tempPath_(temporaryName(path_)) {}

AtomicPath::~AtomicPath() {
  if (!committed_) std::remove(tempPath_.c_str());
}

void AtomicPath::commit() {
  std::error_code ec;
  std::filesystem::rename(tempPath_, path_, ec);
  if (ec) throw RuntimeFailure("cannot rename " + tempPath_ + " to " + path_ + ": " + ec.message());
  committed_ = true;
}

bool ensureDirectory(const std::string& dir) {
  std::error_code ec;
  const bool existed = std::filesystem::exists(dir, ec);
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw InputError(dir, 0, "cannot create output directory" + (ec ? ": " + ec.message() : ""));
  return !existed;
}

}  // namespace rad
