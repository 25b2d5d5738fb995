#pragma once
// Bitwise comparison of two arrays of plain values (checkpoint resume, thread determinism).
#include <cstring>
#include <vector>

namespace sloshsph::test {

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

}  // namespace sloshsph::test
