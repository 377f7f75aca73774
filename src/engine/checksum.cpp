#include "engine/checksum.hpp"

#include <array>

namespace pdq {

namespace {

// The reflected CRC-32 tables of the polynomial 0xEDB88320: t[0] one entry per byte value,
// t[k] that byte's effect k bytes further on, so that eight bytes are folded in at once.
constexpr std::array<std::array<std::uint32_t, 256>, 8> crcTables() {
  std::array<std::array<std::uint32_t, 256>, 8> t{};
  for (std::uint32_t n = 0; n < 256; ++n) {
    std::uint32_t c = n;
    for (int k = 0; k < 8; ++k) c = c & 1 ? 0xEDB88320U ^ (c >> 1) : c >> 1;
    t[0][n] = c;
  }
  for (std::uint32_t n = 0; n < 256; ++n)
    for (int k = 1; k < 8; ++k) t[k][n] = t[0][t[k - 1][n] & 0xFFU] ^ (t[k - 1][n] >> 8);
  return t;
}

constexpr auto kCrc = crcTables();

}  // namespace

std::uint32_t crc32(const void* data, std::size_t size, std::uint32_t crc) {
  const auto* p = static_cast<const unsigned char*>(data);
  crc = ~crc;
  // Eight bytes at a time, read byte by byte (any alignment, any byte order).
  for (; size >= 8; size -= 8, p += 8) {
    const std::uint32_t lo = crc ^ (p[0] | p[1] << 8 | p[2] << 16 | std::uint32_t{p[3]} << 24);
    crc = kCrc[7][lo & 0xFFU] ^ kCrc[6][(lo >> 8) & 0xFFU] ^ kCrc[5][(lo >> 16) & 0xFFU] ^
          kCrc[4][lo >> 24] ^ kCrc[3][p[4]] ^ kCrc[2][p[5]] ^ kCrc[1][p[6]] ^ kCrc[0][p[7]];
  }
  for (; size > 0; --size, ++p) crc = kCrc[0][(crc ^ *p) & 0xFFU] ^ (crc >> 8);
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
