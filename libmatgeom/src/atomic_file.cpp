#include "matgeom/atomic_file.h"

#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include <unistd.h>

namespace matgeom {
namespace fs = std::filesystem;
namespace {

void write_bytes(const fs::path& file, const fs::path& named, std::string_view bytes) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) throw std::runtime_error(named.string() + ": cannot write " + file.string());
}

void remove_quietly(const fs::path& file) {
  std::error_code ignored;
  fs::remove(file, ignored);
}

}  // namespace

fs::path temporary_path(const fs::path& path) {
  const std::string name = "." + path.stem().string() + ".tmp-" + std::to_string(::getpid()) +
                           path.extension().string();
  return path.parent_path() / name;
}

void write_atomically(const fs::path& path, const std::function<void(const fs::path& temporary)>& write) {
  const fs::path temporary = temporary_path(path);
  try {
    write(temporary);
  } catch (...) {
    remove_quietly(temporary);
    throw;
  }
  std::error_code error;
  fs::rename(temporary, path, error);
  if (error) {
    remove_quietly(temporary);
    throw std::runtime_error(path.string() + ": cannot rename " + temporary.string() + " to it: " + error.message());
  }
}

void write_file_atomically(const fs::path& path, std::string_view bytes) {
  write_atomically(path, [&](const fs::path& temporary) { write_bytes(temporary, path, bytes); });
}

AtomicFileSet::~AtomicFileSet() {
  for (size_t i = committed_; i < staged_.size(); ++i) remove_quietly(staged_[i].temporary);
}

void AtomicFileSet::stage(const fs::path& destination, std::string_view bytes) {
  stage_with(destination, [&](const fs::path& temporary) { write_bytes(temporary, named_, bytes); });
}

void AtomicFileSet::stage_with(const fs::path& destination, const std::function<void(const fs::path& temporary)>& write) {
  // Recorded first, so that the destructor removes the temporary whatever `write` leaves.
  staged_.push_back({destination, temporary_path(destination), false});
  write(staged_.back().temporary);
}

void AtomicFileSet::commit() {
  // A directory in the way would stop the renames halfway: refuse before the first.
  for (size_t i = committed_; i < staged_.size(); ++i) {
    std::error_code error;
    if (fs::is_directory(staged_[i].destination, error))
      throw std::runtime_error(named_.string() + ": cannot write " + staged_[i].destination.string() +
                               ": a directory of that name is in the way");
  }
  for (; committed_ < staged_.size(); ++committed_) {
    Staged& file = staged_[committed_];
    std::error_code error;
    file.replaces = fs::exists(file.destination, error);
    fs::rename(file.temporary, file.destination, error);
    if (error) {
      for (size_t i = 0; i < committed_; ++i)
        if (!staged_[i].replaces) remove_quietly(staged_[i].destination);
      throw std::runtime_error(named_.string() + ": cannot rename " + file.temporary.string() + " to " +
                               file.destination.string() + ": " + error.message());
    }
  }
}

}  // namespace matgeom
