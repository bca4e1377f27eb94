#include "matbase/memory_limit.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

namespace matbase {
namespace {

uint64_t physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page_size > 0 ? static_cast<uint64_t>(pages) * static_cast<uint64_t>(page_size) : UINT64_MAX;
}

// The limit of this process's memory cgroup: v2's memory.max ("max" when unlimited) or v1's
// memory.limit_in_bytes, under the group's own path or, inside a container, at the root.
uint64_t cgroup_memory_bytes() {
  std::ifstream groups("/proc/self/cgroup");
  std::string line, v2_path, v1_path;
  while (std::getline(groups, line)) {
    if (line.rfind("0::", 0) == 0) v2_path = line.substr(3);
    const size_t memory = line.find(":memory:");
    if (memory != std::string::npos) v1_path = line.substr(memory + 8);
  }
  const std::string files[] = {"/sys/fs/cgroup" + v2_path + "/memory.max", "/sys/fs/cgroup/memory.max",
                               "/sys/fs/cgroup/memory" + v1_path + "/memory.limit_in_bytes",
                               "/sys/fs/cgroup/memory/memory.limit_in_bytes"};
  uint64_t smallest = UINT64_MAX;
  for (const std::string& file : files) {
    std::ifstream in(file);
    unsigned long long limit = 0;
    if (in >> limit) smallest = std::min<uint64_t>(smallest, limit);
  }
  return smallest;
}

uint64_t address_space_bytes() {
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return UINT64_MAX;
  return limit.rlim_cur;
}

}  // namespace

uint64_t memory_limit_bytes() {
  // The machine's and the cgroup's limits are read once (files under /proc and /sys: every
  // decoded dataset image asks); ulimit -v is one system call, so a change to it is seen.
  static const uint64_t machine_limit = std::min(physical_memory_bytes(), cgroup_memory_bytes());
  return std::min(machine_limit, address_space_bytes());
}

std::string byte_size_text(double bytes) {
  const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int unit = 0;
  while (bytes >= 1024.0 && unit < 6) {
    bytes /= 1024.0;
    ++unit;
  }
  char text[64];
  std::snprintf(text, sizeof text, unit == 0 ? "%.0f %s" : "%.1f %s", bytes, units[unit]);
  return text;
}

std::optional<std::string> memory_problem(double bytes, const std::string& what) {
  const uint64_t limit = memory_limit_bytes();
  if (bytes <= static_cast<double>(limit)) return std::nullopt;
  return "needs " + byte_size_text(bytes) + " for " + what + ", more than the " +
         byte_size_text(static_cast<double>(limit)) + " of memory this process can have";
}

void require_memory(double bytes, const std::string& what, const std::string& owner) {
  if (const std::optional<std::string> problem = memory_problem(bytes, what))
    throw std::runtime_error(owner + ": " + *problem);
}

}  // namespace matbase
