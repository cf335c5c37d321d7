#pragma once
// The process's memory budget (`tessref --max-memory`): a bound on the memory tessref maps for its
// data, so that a scene asking for more than the machine has ends in an error that names the
// budget, not in swapping or the kernel's out-of-memory killer. Enforced by the kernel
// (RLIMIT_DATA: the heap and every private writable mapping), so it costs nothing per allocation;
// an allocation past it throws std::bad_alloc, which the command reports.
#include <cstdint>
#include <string>

namespace tessref {

// The smallest budget tessref accepts: its libraries take about 100 MiB of it before any work.
inline constexpr std::uint64_t kMinMemoryBudget = std::uint64_t(256) << 20;

// The memory this process may use: the machine's physical memory, or the cgroup's limit (a
// container's) where that is lower. 0 where neither can be read.
std::uint64_t machine_memory_bytes();

// The default budget: three quarters of machine_memory_bytes() (room for the page cache and the
// rest of the machine); 0, no budget, where the machine's memory cannot be read or three
// quarters of it is under kMinMemoryBudget.
std::uint64_t default_memory_budget();

// Sets the budget (0: none). Returns false where it cannot be enforced: in AddressSanitizer builds,
// whose shadow memory alone passes any budget, or where the kernel refuses the limit.
bool set_memory_budget(std::uint64_t bytes);

// The budget set by set_memory_budget (0: none).
std::uint64_t memory_budget();

// "1.5 GiB", "64.0 MiB", "512 bytes": sizes in messages.
std::string format_bytes(std::uint64_t bytes);

}  // namespace tessref
