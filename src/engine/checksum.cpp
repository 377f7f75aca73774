#include "engine/checksum.hpp"

#include <array>

namespace pdq {

namespace {

// The reflected CRC-32 table of the polynomial 0xEDB88320, one entry per byte value.
constexpr std::array<std::uint32_t, 256> crcTable() {
  std::array<std::uint32_t, 256> t{};
  for (std::uint32_t n = 0; n < 256; ++n) {
    std::uint32_t c = n;
    for (int k = 0; k < 8; ++k) c = c & 1 ? 0xEDB88320U ^ (c >> 1) : c >> 1;
    t[n] = c;
  }
  return t;
}

constexpr auto kCrc = crcTable();

}  // namespace

std::uint32_t crc32(const void* data, std::size_t size, std::uint32_t crc) {
  const auto* p = static_cast<const unsigned char*>(data);
  crc = ~crc;
  for (std::size_t k = 0; k < size; ++k) crc = kCrc[(crc ^ p[k]) & 0xFFU] ^ (crc >> 8);
  return ~crc;
}

std::uint64_t hash64(std::string_view bytes, std::uint64_t hash) {
  for (unsigned char c : bytes) {
    hash ^= c;
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

}  // namespace pdq
