#include "query_sets.hpp"

#include <cstdio>

#include "io/output_file.hpp"

namespace exactccd::cli {

void write_query_file(const std::string& path, const std::vector<bool>& truth, const std::string& note,
                      const std::function<void(std::ostream&)>& write) {
  io::AtomicOutputFile out(path);
  write(out.stream());
  out.commit();
  std::size_t positives = 0;
  for (const bool t : truth) positives += t;
  std::printf("%s: %zu queries, %zu positives%s\n", path.c_str(), truth.size(), positives, note.c_str());
}

}  // namespace exactccd::cli
