#include "fuzz/readers/reader_oracle.hpp"

#include <sanitizer/allocator_interface.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/benchmark_csv.hpp"  // ParseError

namespace exactccd::fuzzing {
namespace {

// The allocation meter. The sanitizer's allocator calls these hooks on every malloc and free of
// every thread, so what they update must be global; it is thread-local (the meter of one
// thread) and only read and written by run_reader's thread while it is metering.
thread_local bool metering = false;
thread_local long long held = 0;       // bytes allocated minus bytes freed since metering began
thread_local long long peak_held = 0;  // the largest `held` seen

void on_malloc(const volatile void*, std::size_t size) {
  if (!metering) return;
  held += static_cast<long long>(size);
  peak_held = std::max(peak_held, held);
}

void on_free(const volatile void* p) {
  // Called before the block is released, so its size is still known. Blocks allocated before
  // metering began count too: `held` may go below 0, which only lowers the peak's baseline.
  if (!metering || p == nullptr) return;
  held -= static_cast<long long>(__sanitizer_get_allocated_size(const_cast<const void*>(p)));
}

bool install_hooks() { return __sanitizer_install_malloc_and_free_hooks(on_malloc, on_free) != 0; }

/// Metering on for one scope.
class Meter {
 public:
  Meter() {
    static const bool installed = install_hooks();
    if (!installed) std::fprintf(stderr, "reader fuzz: cannot install the allocation hooks\n"), std::abort();
    held = peak_held = 0;
    metering = true;
  }
  ~Meter() { metering = false; }
  Meter(const Meter&) = delete;
  Meter& operator=(const Meter&) = delete;
  long long peak() const { return peak_held; }
};

bool starts_with(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

/// The number N of "byte offset N" right after the source's "<source>: ", or -1.
long long byte_offset(const std::string& message, const std::string& source) {
  const std::string prefix = source + ": byte offset ";
  if (!starts_with(message, prefix)) return -1;
  std::size_t i = prefix.size();
  long long n = 0;
  if (i >= message.size() || !std::isdigit(static_cast<unsigned char>(message[i]))) return -1;
  for (; i < message.size() && std::isdigit(static_cast<unsigned char>(message[i])); ++i) {
    n = n * 10 + (message[i] - '0');
    if (n > (1LL << 50)) return -1;
  }
  return n;
}

}  // namespace

void fail(const std::string& what, std::string_view input) {
  std::fprintf(stderr, "reader fuzz violation: %s\ninput (%zu bytes): \"", what.c_str(), input.size());
  for (std::size_t i = 0; i < std::min<std::size_t>(input.size(), 2000); ++i) {
    const auto c = static_cast<unsigned char>(input[i]);
    if (c == '\\' || c == '"') std::fprintf(stderr, "\\%c", c);
    else if (c == '\n') std::fprintf(stderr, "\\n");
    else if (std::isprint(c)) std::fputc(c, stderr);
    else std::fprintf(stderr, "\\x%02x", c);
  }
  std::fprintf(stderr, "\"%s\n", input.size() > 2000 ? "..." : "");
  std::abort();
}

std::size_t line_count(std::string_view text) {
  const std::size_t newlines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
  return std::max<std::size_t>(1, newlines + (!text.empty() && text.back() != '\n' ? 1 : 0));
}

std::size_t nonblank_lines(std::string_view text) {
  std::size_t count = 0;
  bool seen = false;
  for (const char c : text) {
    if (c == '\n') {
      count += seen ? 1 : 0;
      seen = false;
    } else if (!std::isspace(static_cast<unsigned char>(c))) {
      seen = true;
    }
  }
  return count + (seen ? 1 : 0);
}

void check_error(const io::InputError& error, const std::string& source, Location where, std::string_view input) {
  const std::string message = error.what();
  require(error.source() == source && starts_with(message, source + ":"),
          "the error does not start with the source name '" + source + "': " + message, input);
  if (const auto* parse = dynamic_cast<const io::ParseError*>(&error)) {
    require(parse->line() >= 1 && parse->line() <= line_count(input),
            "the error names line " + std::to_string(parse->line()) + " of an input of " +
                std::to_string(line_count(input)) + " lines: " + message,
            input);
    require(starts_with(message, source + ":" + std::to_string(parse->line()) + ": "),
            "the error's message does not say its line: " + message, input);
    return;
  }
  require(where != Location::line, "a text reader's error without a line: " + message, input);
  const long long offset = byte_offset(message, source);
  if (offset >= 0) {
    require(static_cast<unsigned long long>(offset) <= input.size(),
            "the error names byte offset " + std::to_string(offset) + " of an input of " +
                std::to_string(input.size()) + " bytes: " + message,
            input);
    return;
  }
  require(where == Location::any, "a binary reader's error without a byte offset: " + message, input);
}

ReaderOutcome run_reader(const std::function<void()>& parse, const std::string& source, Location where,
                         std::string_view input) {
  ReaderOutcome outcome;
  long long peak = 0;
  {
    const Meter meter;  // any other exception than InputError leaves here: libFuzzer reports it
    try {
      parse();
      outcome.accepted = true;
      peak = meter.peak();
    } catch (const io::InputError& e) {
      peak = meter.peak();  // before check_error, which allocates
      check_error(e, source, where, input);
      outcome.error = e.what();
    }
  }
  const long long bound = static_cast<long long>(kBytesPerInputByte * input.size() + kFixedBytes);
  require(peak <= bound,
          "the reader held " + std::to_string(peak) + " bytes at once for an input of " + std::to_string(input.size()) +
              " bytes (more than " + std::to_string(kBytesPerInputByte) + " per byte + " +
              std::to_string(kFixedBytes) + ")",
          input);
  return outcome;
}

ScratchFile::ScratchFile(const std::string& name)
    : path_((std::filesystem::temp_directory_path() /
             ("exactccd-fuzz-" + std::to_string(static_cast<long long>(getpid())) + "-" + name))
                .string()) {}

ScratchFile::~ScratchFile() {
  std::error_code ec;
  std::filesystem::remove(path_, ec);
}

const std::string& ScratchFile::write(std::string_view bytes) {
  std::ofstream out(path_, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) std::fprintf(stderr, "reader fuzz: cannot write %s\n", path_.c_str()), std::abort();
  return path_;
}

void check_rejects_trailing_garbage(const std::function<void(std::istream&)>& read, std::string_view input) {
  std::istringstream in(std::string(input) + "\nx\n");
  try {
    read(in);
  } catch (const io::InputError&) {
    return;
  }
  fail("the input with a line 'x' appended is accepted too", input);
}

}  // namespace exactccd::fuzzing
