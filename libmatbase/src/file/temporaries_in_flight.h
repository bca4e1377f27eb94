#pragma once
// The temporaries this process is writing, recorded so that a signal handler can remove them
// before the process ends (atomic_file.h, remove_temporaries_in_flight). A fixed table of plain
// character buffers and lock-free flags: nothing a handler touches allocates or locks.
#include <filesystem>

namespace matbase {

// Records `temporary`; returns its slot, or -1 when the table is full (the file is then only
// removed by the normal paths, not by a handler).
int record_temporary(const std::filesystem::path& temporary) noexcept;
// The temporary in `slot` was renamed or removed.
void forget_temporary(int slot) noexcept;

}  // namespace matbase
