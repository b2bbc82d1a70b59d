// Fields: the whitespace-separated fields of one text line with fast (std::from_chars), checked,
// typed access. The first failed access is kept as the reason the line is malformed.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/Pose2D.h"

namespace rgnav {

// A whole field as a number ("nan" and "inf" included; a leading '+' is allowed).
std::optional<double> parseNumber(std::string_view field);
// A whole field as a non-negative integer.
std::optional<std::size_t> parseCount(std::string_view field);
// A field fit for an error message: quoted, at most a few dozen characters, printable.
std::string quoteField(std::string_view field);

class Fields {
 public:
  // Splits `line` at spaces and tabs and clears any earlier failure. The views point into `line`.
  void split(std::string_view line);

  std::size_t size() const { return fields_.size(); }
  std::string_view operator[](std::size_t i) const { return fields_[i]; }

  // Typed access to field i; a missing or bad field records a failure and gives 0.
  double number(std::size_t i, std::string_view name);
  double finite(std::size_t i, std::string_view name);
  std::size_t count(std::size_t i, std::string_view name, std::size_t max);
  Pose2D pose(std::size_t i, std::string_view name);  // finite fields i, i+1, i+2 as x y theta
  // Replaces `out` with fields first .. first+n-1 as numbers; checks the range before reserving.
  void numbers(std::size_t first, std::size_t n, std::string_view name, std::vector<double>& out);

  // Records `reason` unless an earlier failure is held.
  void fail(std::string reason);
  bool failed() const { return !failure_.empty(); }
  const std::string& failure() const { return failure_; }

 private:
  bool present(std::size_t i, std::string_view name);

  std::vector<std::string_view> fields_;
  std::string failure_;
};

}  // namespace rgnav
