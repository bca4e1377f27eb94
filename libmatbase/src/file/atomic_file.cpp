#include "matbase/file/atomic_file.h"

#include <cctype>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include "file/temporaries_in_flight.h"

namespace matbase {
namespace fs = std::filesystem;
namespace {

// POSIX calls rather than a stream, so that the error says why: "<failure>: No space left on
// device".
void write_bytes(const fs::path& file, const std::string& failure, std::string_view bytes) {
  const auto fail = [&](int error) { throw std::runtime_error(failure + ": " + std::strerror(error)); };
  const int descriptor = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (descriptor < 0) fail(errno);
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t written = ::write(descriptor, bytes.data() + done, bytes.size() - done);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) {
      const int error = written < 0 ? errno : ENOSPC;
      ::close(descriptor);
      fail(error);
    }
    done += static_cast<size_t>(written);
  }
  if (::close(descriptor) != 0) fail(errno);
}

void remove_quietly(const fs::path& file) {
  std::error_code ignored;
  fs::remove(file, ignored);
}

// This machine's name as it may appear in a file name: letters, digits and '-' only.
const std::string& host_tag() {
  static const std::string tag = [] {
    char name[256] = {};
    if (::gethostname(name, sizeof(name) - 1) != 0) return std::string("host");
    std::string text;
    for (const char* c = name; *c; ++c)
      text += (std::isalnum(static_cast<unsigned char>(*c)) || *c == '-') ? *c : '-';
    return text.empty() ? std::string("host") : text;
  }();
  return tag;
}

}  // namespace

fs::path temporary_path(const fs::path& path) {
  const std::string name = "." + path.stem().string() + ".tmp-" + host_tag() + "-" + std::to_string(::getpid()) +
                           path.extension().string();
  return path.parent_path() / name;
}

void remove_stale_temporaries(const fs::path& path, bool any_process) {
  const std::string prefix = "." + path.stem().string() + ".tmp-", extension = path.extension().string();
  const std::string local = prefix + host_tag() + "-";
  std::error_code error;
  for (fs::directory_iterator it(path.parent_path(), error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.size() <= prefix.size() + extension.size() || name.compare(0, prefix.size(), prefix) != 0 ||
        name.compare(name.size() - extension.size(), extension.size(), extension) != 0)
      continue;
    if (!any_process) {
      // Only this machine's, and only of a process that is gone: kill(pid, 0) fails with ESRCH.
      if (name.compare(0, local.size(), local) != 0) continue;
      const std::string pid_text = name.substr(local.size(), name.size() - local.size() - extension.size());
      if (pid_text.empty() || pid_text.find_first_not_of("0123456789") != std::string::npos) continue;
      const long pid = std::stol(pid_text);
      if (pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
    }
    remove_quietly(it->path());
  }
}

void write_atomically(const fs::path& path, const std::function<void(const fs::path& temporary)>& write) {
  const fs::path temporary = temporary_path(path);
  struct Record {
    int slot;
    ~Record() { forget_temporary(slot); }
  } record{record_temporary(temporary)};
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

void write_file_atomically(const fs::path& path, std::string_view bytes, AtomicFileSet* set) {
  if (set) return set->stage(path, bytes);
  write_atomically(path, [&](const fs::path& temporary) { write_bytes(temporary, path.string() + ": cannot write", bytes); });
}

AtomicFileSet::~AtomicFileSet() {
  for (size_t i = committed_; i < staged_.size(); ++i) {
    remove_quietly(staged_[i].temporary);
    forget_temporary(staged_[i].record);
  }
}

void AtomicFileSet::stage(const fs::path& destination, std::string_view bytes) {
  // Recorded first, so that the destructor removes the temporary whatever a failed write leaves.
  staged_.push_back({destination, temporary_path(destination)});
  staged_.back().record = record_temporary(staged_.back().temporary);
  write_bytes(staged_.back().temporary, named_.string() + ": cannot write " + destination.string(), bytes);
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
    forget_temporary(file.record);
  }
}

OutputFolder::OutputFolder(fs::path path) : path_(std::move(path)) {
  std::error_code error;
  made_ = fs::create_directories(path_, error);
  if (error) throw std::runtime_error(path_.string() + ": cannot create the folder: " + error.message());
}

OutputFolder::~OutputFolder() {
  std::error_code ignored;
  if (made_) fs::remove(path_, ignored);  // fails, as it should, unless empty
}

}  // namespace matbase
