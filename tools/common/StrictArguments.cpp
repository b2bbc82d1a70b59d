// Strict parsing of command-line numbers (StrictArguments.h).
#include "tools/common/StrictArguments.h"

#include <charconv>
#include <cmath>

namespace rgnav {

namespace {

// "<argument> '<text>' <problem>", built by appending (GCC 12 misreads the operator+ chain as an
// overlapping copy, -Wrestrict).
std::string describe(const std::string& argument, const std::string& text, const std::string& problem) {
  std::string message = argument;
  message.append(" '").append(text).append("' ").append(problem);
  return message;
}

}  // namespace

ArgumentError::ArgumentError(const std::string& argument, const std::string& text, const std::string& problem)
    : InvalidArgumentError(describe(argument, text, problem)), argument_(argument), text_(text) {}

std::uint64_t parseWholeNumber(std::string_view text, const std::string& argument, std::uint64_t max) {
  const std::string shown(text);
  if (text.empty() || text.find_first_not_of("0123456789") != std::string_view::npos)
    throw ArgumentError(argument, shown, "is not a whole number");
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error == std::errc::result_out_of_range || value > max)
    throw ArgumentError(argument, shown, "is too large (at most " + std::to_string(max) + ")");
  return value;
}

std::uint64_t parseId(std::string_view text, const std::string& argument) {
  const std::uint64_t id = parseWholeNumber(text, argument);
  if (id == 0) throw ArgumentError(argument, std::string(text), "is not an ID (IDs start at 1)");
  return id;
}

double parseFiniteNumber(std::string_view text, const std::string& argument) {
  const std::string shown(text);
  double value = 0.0;
  const char* last = text.data() + text.size();
  const auto [end, error] = std::from_chars(text.data(), last, value);
  if (text.empty() || error == std::errc::invalid_argument || end != last)
    throw ArgumentError(argument, shown, "is not a number");
  if (error == std::errc::result_out_of_range || !std::isfinite(value))
    throw ArgumentError(argument, shown, "is not a finite number");
  return value;
}

}  // namespace rgnav
