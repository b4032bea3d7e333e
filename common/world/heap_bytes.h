#pragma once
// What a vector holds on the heap, for the memory counts of chapter 9's snapshots and history and
// of chapter 11's handed joint rows: the room it keeps (capacity), which is what it costs, and the
// part in use (size).

#include <cstddef>
#include <vector>

namespace stepwise {

/// Bytes of the vector's room: capacity times the element's size.
template <class T>
std::size_t capacityBytes(const std::vector<T>& values) {
    return values.capacity() * sizeof(T);
}

/// Bytes of the elements in use: size times the element's size.
template <class T>
std::size_t sizeBytes(const std::vector<T>& values) {
    return values.size() * sizeof(T);
}

}  // namespace stepwise
