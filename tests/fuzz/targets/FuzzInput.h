// Fuzz input helpers: the bytes as a string, or as a file for the parsers that read only files
// (they detect plain, gzip and xz data by its magic bytes, so a file also reaches the decoders).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace rgnav::fuzz {

inline std::string fuzzText(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

// Writes the bytes to this process's input file (in a private folder under /dev/shm, or the
// temp folder where there is none; removed at exit) and returns its path.
std::string fuzzInputFile(const std::uint8_t* data, std::size_t size);

}  // namespace rgnav::fuzz
