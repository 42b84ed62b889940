#include "io/output_file.hpp"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "io/input_file.hpp"  // UsageError

namespace exactccd::io {
namespace {

namespace fs = std::filesystem;

/// A fresh temporary name next to `path`.
std::string temporary_name(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  return path + ".tmp." + std::to_string(getpid()) + "." + std::to_string(counter++);
}

std::string system_reason(int error) { return error ? std::strerror(error) : "unknown reason"; }

}  // namespace

AtomicOutputFile::AtomicOutputFile(const std::string& path) : path_(path), temporary_(temporary_name(path)) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw UsageError(path + ": is a directory (expected a file name)");
  errno = 0;
  out_.open(temporary_, std::ios::binary | std::ios::trunc);
  if (!out_) {
    const int error = errno;
    throw UsageError(path + ": cannot write: " + system_reason(error));
  }
}

AtomicOutputFile::~AtomicOutputFile() {
  if (committed_) return;
  out_.close();
  std::remove(temporary_.c_str());
}

void AtomicOutputFile::commit() {
  out_.flush();
  const bool written = static_cast<bool>(out_);
  out_.close();
  if (!written || out_.fail()) throw UsageError(path_ + ": write error (" + temporary_ + " not renamed)");
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) {
    const int error = errno;
    throw UsageError(path_ + ": cannot write: " + system_reason(error));
  }
  committed_ = true;
}

void write_file_atomically(const std::string& path, const std::string& text) {
  AtomicOutputFile file(path);
  file.stream() << text;
  file.commit();
}

void prepare_output_directory(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (status.type() != fs::file_type::not_found && status.type() != fs::file_type::directory &&
      status.type() != fs::file_type::none)
    throw UsageError(path + ": not a directory");
  if (status.type() != fs::file_type::directory) {
    fs::create_directories(path, ec);
    if (ec || !fs::is_directory(path))
      throw UsageError(path + ": cannot create directory: " + (ec ? ec.message() : "not a directory"));
  }
  const std::string probe = temporary_name((fs::path(path) / ".exactccd-write-probe").string());
  errno = 0;
  std::ofstream out(probe, std::ios::binary | std::ios::trunc);
  if (!out) {
    const int error = errno;
    throw UsageError(path + ": cannot write: " + system_reason(error));
  }
  out.close();
  std::remove(probe.c_str());
}

}  // namespace exactccd::io
