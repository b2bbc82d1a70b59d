// Base64 (RFC 4648, section 4: the standard alphabet with "=" padding, no line breaks) of the
// freespace bitmaps in the RG Map's JSON export (RgMapJson.h). decodeBase64 is for readers of
// that file, e.g. a GUI or a test.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rgnav {

std::string encodeBase64(std::span<const std::uint8_t> bytes);

// Throws InvalidArgumentError for a length that is not a multiple of 4, a character outside the
// alphabet, or padding anywhere but at the end.
std::vector<std::uint8_t> decodeBase64(std::string_view text);

}  // namespace rgnav
