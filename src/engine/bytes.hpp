#pragma once
// Plain values in and out of the byte blocks that Context::gather and broadcast carry.
#include <cstring>
#include <vector>

namespace pdq::bytes {

template <class T>
void append(std::vector<char>& out, const T* data, std::size_t n) {
  const std::size_t at = out.size();
  out.resize(at + n * sizeof(T));
  if (n) std::memcpy(out.data() + at, data, n * sizeof(T));
}

template <class T>
void take(const char*& in, T* data, std::size_t n) {
  if (n) std::memcpy(data, in, n * sizeof(T));
  in += n * sizeof(T);
}

}  // namespace pdq::bytes
