#pragma once
// Writing files so that no reader ever finds one half-written, used by every library and app:
// each file is written under a temporary name beside its destination (the same folder, so the
// rename is atomic) and renamed into place only when complete. On any failure the temporary is
// removed and the destination is left as it was.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string_view>
#include <utility>
#include <vector>

namespace matbase {

// The temporary name for `path`: hidden, unique to this process (its machine's name and its
// process id, so processes on the nodes of a cluster that share the folder never collide), in the
// same folder and with the same extension, so writers that pick the format from the extension
// still see it: "dir/.name.tmp-node07-1234.ext".
std::filesystem::path temporary_path(const std::filesystem::path& path);

// Removes the temporaries of `path` that processes killed outright (SIGKILL, a lost node) left
// behind. any_process: every temporary of `path`, whoever made it (for a file only this process
// writes now, as one shard's frames); else only those of this machine's processes that have
// ended. Errors are ignored: a temporary that stays is harmless.
void remove_stale_temporaries(const std::filesystem::path& path, bool any_process);

// Calls write(temporary) to write the whole file, then renames the temporary to `path`. The
// folder must exist: a missing one is an error of the caller's input, not something to make. An
// exception from `write` is rethrown as it is; a failed rename throws std::runtime_error starting
// with `path`. Either way the temporary is gone.
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path& temporary)>& write);

class AtomicFileSet;

// Removes every temporary this process is writing at this moment. Async-signal-safe (it only
// reads a fixed table and calls unlink), for a handler that ends the process on a second Ctrl-C:
// even then no temporary is left beside the outputs.
void remove_temporaries_in_flight() noexcept;

// `bytes` as the whole of the file `path`; std::runtime_error starting with `path` on failure.
// Given a set, the file is staged there instead, to appear with the set's others.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes, AtomicFileSet* set = nullptr);

// Several files that must appear together (an OBJ with its MTL and textures, a view's images):
// each staged under its temporary name, then all renamed by commit() in staging order, so the one
// staged last (the file readers open first) appears last. commit() first checks that no
// destination is a directory; if a rename fails, the files this commit created are removed
// again; the destructor removes whatever was staged and not committed.
class AtomicFileSet {
 public:
  // `named`: the path errors start with (the file the set is written for).
  explicit AtomicFileSet(std::filesystem::path named) : named_(std::move(named)) {}
  AtomicFileSet(const AtomicFileSet&) = delete;
  AtomicFileSet& operator=(const AtomicFileSet&) = delete;
  ~AtomicFileSet();

  // Writes `bytes` to the temporary of `destination`; std::runtime_error on failure.
  void stage(const std::filesystem::path& destination, std::string_view bytes);
  // std::runtime_error naming the file that could not be renamed.
  void commit();

 private:
  struct Staged {
    std::filesystem::path destination;
    std::filesystem::path temporary;
    int record = -1;        // its slot among the temporaries in flight
    bool replaces = false;  // the destination existed before the commit
  };
  std::filesystem::path named_;
  std::vector<Staged> staged_;
  size_t committed_ = 0;
};

// A folder made for outputs, removed again (if still empty) unless keep() is called: a run whose
// writes failed leaves no trace, not even an empty folder.
class OutputFolder {
 public:
  // Creates `path` and any missing parents; std::runtime_error naming it on failure.
  explicit OutputFolder(std::filesystem::path path);
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;
  ~OutputFolder();

  // The outputs are in place: the folder stays.
  void keep() { made_ = false; }

 private:
  std::filesystem::path path_;
  bool made_ = false;  // this object created the folder
};

}  // namespace matbase
