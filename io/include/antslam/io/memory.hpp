#pragma once
// Upper bounds that reflect memory: an option whose value would make a run allocate more than
// the machine has is refused up front, naming the option and the memory it would need, instead
// of ending in std::bad_alloc (or the kernel's out-of-memory killer) after minutes of work.

#include <cstdint>
#include <string>
#include <string_view>

namespace antslam::io {

/// Bytes this process may allocate: the machine's physical memory, or the address-space limit
/// (ulimit -v) if that is lower.
std::uint64_t memory_limit_bytes();

/// "1.5 GB", "820 kB": a byte count for messages (decimal units).
std::string format_bytes(double bytes);

/// Throws UsageError "<what> needs about <bytes> of memory, more than the <limit> this machine
/// has" if `bytes` exceeds memory_limit_bytes(). `what` names the option and its value, e.g.
/// "--trials 1000000000 (the trials' results)".
void require_memory(std::string_view what, double bytes);

}  // namespace antslam::io
