// Fields: splitting, from_chars conversion and the first-failure bookkeeping.
#include "core/logs/Fields.h"

#include <charconv>
#include <cmath>

namespace rgnav {

namespace {

constexpr std::size_t kQuotedMax = 32;

bool isBlank(char c) { return c == ' ' || c == '\t'; }

}  // namespace

std::optional<double> parseNumber(std::string_view field) {
  if (field.size() > 1 && field.front() == '+' && field[1] != '-') {
    field.remove_prefix(1);
  }
  double value = 0.0;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (error != std::errc() || end != field.data() + field.size()) {
    return std::nullopt;
  }
  return value;
}

std::optional<std::size_t> parseCount(std::string_view field) {
  std::size_t value = 0;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (error != std::errc() || end != field.data() + field.size()) {
    return std::nullopt;
  }
  return value;
}

std::string quoteField(std::string_view field) {
  std::string quoted = "'";
  for (const char c : field.substr(0, kQuotedMax)) {
    const auto byte = static_cast<unsigned char>(c);
    quoted += byte >= 0x20 && byte < 0x7f ? c : '?';
  }
  return quoted + (field.size() > kQuotedMax ? "...'" : "'");
}

void Fields::split(std::string_view line) {
  fields_.clear();
  failure_.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && isBlank(line[i])) {
      ++i;
    }
    const std::size_t start = i;
    while (i < line.size() && !isBlank(line[i])) {
      ++i;
    }
    if (i > start) {
      fields_.push_back(line.substr(start, i - start));
    }
  }
}

bool Fields::present(std::size_t i, std::string_view name) {
  if (i < fields_.size()) {
    return true;
  }
  fail("missing " + std::string(name));
  return false;
}

double Fields::number(std::size_t i, std::string_view name) {
  if (!present(i, name)) {
    return 0.0;
  }
  const auto value = parseNumber(fields_[i]);
  if (!value) {
    fail(std::string(name) + " is not a number: " + quoteField(fields_[i]));
    return 0.0;
  }
  return *value;
}

double Fields::finite(std::size_t i, std::string_view name) {
  const double value = number(i, name);
  if (!std::isfinite(value)) {
    fail(std::string(name) + " is not finite: " + quoteField(fields_[i]));
    return 0.0;
  }
  return value;
}

std::size_t Fields::count(std::size_t i, std::string_view name, std::size_t max) {
  if (!present(i, name)) {
    return 0;
  }
  const auto value = parseCount(fields_[i]);
  if (!value) {
    fail(std::string(name) + " is not a count: " + quoteField(fields_[i]));
    return 0;
  }
  if (*value > max) {
    fail(std::string(name) + " " + std::to_string(*value) + " exceeds the limit of " +
         std::to_string(max));
    return 0;
  }
  return *value;
}

Pose2D Fields::pose(std::size_t i, std::string_view name) {
  const std::string prefix(name);
  const double x = finite(i, prefix + " x");
  const double y = finite(i + 1, prefix + " y");
  const double theta = finite(i + 2, prefix + " theta");
  return {x, y, theta};
}

void Fields::numbers(std::size_t first, std::size_t n, std::string_view name,
                     std::vector<double>& out) {
  out.clear();
  if (first > fields_.size() || n > fields_.size() - first) {
    fail("fewer fields than " + std::to_string(n) + " " + std::string(name) + " values");
    return;
  }
  out.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const auto value = parseNumber(fields_[first + k]);
    if (!value) {
      fail(std::string(name) + " " + std::to_string(k + 1) + " is not a number: " +
           quoteField(fields_[first + k]));
      return;
    }
    out.push_back(*value);
  }
}

void Fields::fail(std::string reason) {
  if (failure_.empty()) {
    failure_ = std::move(reason);
  }
}

}  // namespace rgnav
