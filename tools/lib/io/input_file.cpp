#include "io/input_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <istream>
#include <system_error>

namespace exactccd::io {

InputError::InputError(const std::string& source, const std::string& reason)
    : std::runtime_error(source + ": " + reason), source_(source) {}

InputError::InputError(const std::string& source, const std::string& what, bool)
    : std::runtime_error(what), source_(source) {}

ParseError::ParseError(const std::string& source, std::size_t line, const std::string& what)
    : InputError(source, source + ":" + std::to_string(line) + ": " + what, true), line_(line) {}

bool skip_byte_order_mark(std::istream& in) {
  static constexpr unsigned char kBom[3] = {0xEF, 0xBB, 0xBF};
  if (in.peek() != kBom[0]) return false;
  // The first byte matches: read up to three and put back what is not a full mark.
  char got[3] = {};
  std::size_t n = 0;
  while (n < 3 && in.peek() == kBom[n]) got[n++] = static_cast<char>(in.get());
  if (n == 3) return true;
  in.clear();
  while (n > 0) in.putback(got[--n]);
  return false;
}

InputFile::InputFile(const std::string& path, ByteOrderMark mark) : path_(path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (status.type() == fs::file_type::not_found) throw InputError(path, "no such file");
  if (status.type() == fs::file_type::directory)
    throw InputError(path, "is a directory (expected a file)");
  errno = 0;
  in_.open(path, std::ios::binary);
  if (!in_) {
    const int error = errno;
    throw InputError(path, std::string("cannot open: ") + (error ? std::strerror(error) : "unknown reason"));
  }
  if (mark == ByteOrderMark::skip) had_bom_ = skip_byte_order_mark(in_);
}

void InputFile::check_read() const {
  if (in_.bad()) throw InputError(path_, "read error");
}

}  // namespace exactccd::io
