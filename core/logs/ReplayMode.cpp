// ReplayMode: parsing and formatting of the replay mode text.
#include "core/logs/ReplayMode.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>

#include "core/common/Errors.h"
#include "core/logs/Fields.h"

namespace rgnav {

ReplayMode parseReplayMode(std::string_view text) {
  std::string lower(text);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (lower == "realtime") {
    return {ReplayMode::Kind::RealTime, 1.0};
  }
  if (lower == "max" || lower == "asfast") {
    return {ReplayMode::Kind::AsFastAsConsumed, 1.0};
  }
  std::string_view factor(lower);
  if (factor.starts_with('x')) {
    factor.remove_prefix(1);
  }
  const auto speed = parseNumber(factor);
  if (!speed || !std::isfinite(*speed) || *speed <= 0.0) {
    throw ConfigError("replay mode " + quoteField(text) +
                      ": expected \"realtime\", \"x<factor>\" with a positive factor, or \"max\"");
  }
  return {ReplayMode::Kind::RealTime, *speed};
}

std::string formatReplayMode(const ReplayMode& mode) {
  if (mode.kind == ReplayMode::Kind::AsFastAsConsumed) {
    return "asfast";
  }
  if (mode.speed == 1.0) {
    return "realtime";
  }
  std::array<char, 32> digits{};
  const auto result = std::to_chars(digits.data(), digits.data() + digits.size(), mode.speed);
  std::string text = "x";
  text.append(digits.data(), result.ptr);
  return text;
}

}  // namespace rgnav
