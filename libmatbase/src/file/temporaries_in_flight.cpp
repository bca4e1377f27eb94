#include "file/temporaries_in_flight.h"

#include <atomic>
#include <cstring>

#include <unistd.h>

#include "matbase/file/atomic_file.h"

namespace matbase {
namespace {

// More than any set this project stages at once (a view's 19 files, an OBJ with its textures).
constexpr int kSlots = 256;
constexpr size_t kPathBytes = 4096;  // PATH_MAX on Linux

enum SlotState : int { kFree, kClaimed, kRecorded };

struct Slot {
  std::atomic<int> state{kFree};
  char path[kPathBytes];
};
static_assert(std::atomic<int>::is_always_lock_free);

Slot slots[kSlots];

}  // namespace

int record_temporary(const std::filesystem::path& temporary) noexcept {
  const std::string& text = temporary.native();
  if (text.size() >= kPathBytes) return -1;
  for (int i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (!slots[i].state.compare_exchange_strong(expected, kClaimed)) continue;
    std::memcpy(slots[i].path, text.c_str(), text.size() + 1);
    slots[i].state.store(kRecorded);
    return i;
  }
  return -1;
}

void forget_temporary(int slot) noexcept {
  if (slot >= 0) slots[slot].state.store(kFree);
}

void remove_temporaries_in_flight() noexcept {
  for (Slot& slot : slots)
    if (slot.state.load() == kRecorded) ::unlink(slot.path);
}

}  // namespace matbase
