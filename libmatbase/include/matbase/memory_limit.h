#pragma once
// Whether an allocation the input asks for can succeed, checked before making it: an image that
// declares 20000 x 20000 pixels in a 1.2 MB file, or a 100000 x 100000 render, must be refused
// with the size it needs, not end in std::bad_alloc after minutes of swapping.
#include <cstdint>
#include <optional>
#include <string>

namespace matbase {

// The most memory this process can have: the smallest of the machine's physical memory, its
// cgroup's limit (a Slurm job's or a container's allocation) and its address-space limit
// (ulimit -v).
uint64_t memory_limit_bytes();

// Nothing when `bytes` fit within memory_limit_bytes(), else "needs 6.0 GiB for <what>, more than
// the 23.4 GiB of memory this process can have".
std::optional<std::string> memory_problem(double bytes, const std::string& what);

// Throws std::runtime_error "<owner>: needs ... for <what>, more than ..." when memory_problem
// finds one: the check every reader and the renderer make before an allocation an input sized.
void require_memory(double bytes, const std::string& what, const std::string& owner);

// "6.0 GiB", "512 KiB".
std::string byte_size_text(double bytes);

}  // namespace matbase
