#pragma once
// The memory a vector holds, for the footprint a run reports.
#include <cstddef>
#include <vector>

namespace talus {

/// Bytes reserved by v (its capacity, not its size: what the allocator handed out).
template <class T> std::size_t capacity_bytes(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}

} // namespace talus
