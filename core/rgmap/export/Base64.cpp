// Base64 encoding and decoding; see Base64.h.
#include "core/rgmap/export/Base64.h"

#include <algorithm>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

constexpr std::string_view kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

// The 6-bit value of `c`; throws for a character outside the alphabet.
std::uint32_t sextet(char c) {
  const std::size_t at = kAlphabet.find(c);
  if (at == std::string_view::npos) throw InvalidArgumentError("base64: invalid character");
  return static_cast<std::uint32_t>(at);
}

}  // namespace

std::string encodeBase64(std::span<const std::uint8_t> bytes) {
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t group = std::uint32_t(bytes[i]) << 16;
    if (n > 1) group |= std::uint32_t(bytes[i + 1]) << 8;
    if (n > 2) group |= std::uint32_t(bytes[i + 2]);
    for (std::size_t k = 0; k < 4; ++k)
      out += k <= n ? kAlphabet[(group >> (18 - 6 * k)) & 0x3f] : '=';
  }
  return out;
}

std::vector<std::uint8_t> decodeBase64(std::string_view text) {
  if (text.size() % 4 != 0) throw InvalidArgumentError("base64: length is not a multiple of 4");
  std::vector<std::uint8_t> out;
  out.reserve(text.size() / 4 * 3);
  for (std::size_t i = 0; i < text.size(); i += 4) {
    const bool last = i + 4 == text.size();
    const std::size_t padding = last ? (text[i + 3] == '=') + (text[i + 2] == '=') : 0;
    if (padding == 1 && text[i + 2] == '=') throw InvalidArgumentError("base64: misplaced padding");
    std::uint32_t group = 0;
    for (std::size_t k = 0; k < 4; ++k) group = group << 6 | (k < 4 - padding ? sextet(text[i + k]) : 0);
    for (std::size_t k = 0; k < 3 - padding; ++k) out.push_back(std::uint8_t(group >> (16 - 8 * k)));
  }
  return out;
}

}  // namespace rgnav
