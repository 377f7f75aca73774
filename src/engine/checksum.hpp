#pragma once
// Checksums of files pdq writes and reads back: CRC-32 (the polynomial of zlib, gzip and
// PNG, so `crc32` tools agree) detects every burst of up to 32 flipped bits; a 64-bit
// FNV-1a hash names content (a scenario) in a few bytes.
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace pdq {

// `crc` continues an earlier call over the bytes before these (0 to start).
std::uint32_t crc32(const void* data, std::size_t size, std::uint32_t crc = 0);

std::uint64_t hash64(std::string_view bytes, std::uint64_t hash = 0xcbf29ce484222325ULL);

}  // namespace pdq
