// JsonForms: how the checkpoints and exports write numbers, points and poses as JSON
// (nlohmann::json): numbers in the shortest form that reads back to the same double, non-finite
// numbers as "inf", "-inf" and null (NaN), points as [x, y], poses as [x, y, theta], IDs and
// counts as JSON integers. Reading anything else throws FormatError (file "<checkpoint>").
#pragma once

#include <Eigen/Core>
#include <concepts>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/common/Errors.h"
#include "core/common/Pose2D.h"
#include "core/common/TypedId.h"

namespace rgnav {

// A JSON integer on its way into an integer of any type (the type assigned to): a number that is
// not an integer (2.5, 1e99) or does not fit the type is a FormatError, where nlohmann's own
// conversion would truncate it or, out of range, be undefined behaviour.
class JsonInteger {
 public:
  explicit JsonInteger(const nlohmann::json& j) : j_(j) {}

  template <std::integral T>
  operator T() const {  // NOLINT: implicit on purpose, like nlohmann's own conversion
    if (j_.is_number_unsigned()) {
      const auto v = j_.get<std::uint64_t>();
      if (std::in_range<T>(v)) return static_cast<T>(v);
    } else if (j_.is_number_integer()) {
      const auto v = j_.get<std::int64_t>();
      if (std::in_range<T>(v)) return static_cast<T>(v);
    }
    throw FormatError("<checkpoint>", 0, "not an integer in range: " + j_.dump());
  }

  template <class Concept>
  operator TypedId<Concept>() const {  // NOLINT: the field assigned to names the concept
    return TypedId<Concept>(static_cast<std::uint64_t>(*this));
  }

 private:
  const nlohmann::json& j_;
};

inline JsonInteger integerFrom(const nlohmann::json& j) { return JsonInteger(j); }

// An ID is written as its integer and read back through integerFrom, like every integer
// (nlohmann::json finds both through argument-dependent lookup).
template <class Json, class Concept>
void to_json(Json& j, const TypedId<Concept>& id) {
  j = id.value();
}

template <class Concept>
void from_json(const nlohmann::json& j, TypedId<Concept>& id) {
  id = integerFrom(j);
}

// A JSON array of integers into a vector, set or std::array of integers (an array's size must match).
template <class Container>
Container integersFrom(const nlohmann::json& j) {
  if (!j.is_array()) throw FormatError("<checkpoint>", 0, "not a list of integers: " + j.dump());
  using Value = typename Container::value_type;
  Container out{};
  if constexpr (requires { out.push_back(Value{}); }) {
    for (const nlohmann::json& e : j) out.push_back(static_cast<Value>(integerFrom(e)));
  } else if constexpr (requires { out.insert(Value{}); }) {
    for (const nlohmann::json& e : j) out.insert(static_cast<Value>(integerFrom(e)));
  } else {
    if (j.size() != out.size()) throw FormatError("<checkpoint>", 0, "not " + std::to_string(out.size()) + " integers: " + j.dump());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = static_cast<Value>(integerFrom(j[i]));
  }
  return out;
}

nlohmann::json jsonNumber(double v);
double numberFrom(const nlohmann::json& j);

nlohmann::json jsonPoint(const Eigen::Vector2d& p);
Eigen::Vector2d pointFrom(const nlohmann::json& j);

nlohmann::json jsonPoints(const std::vector<Eigen::Vector2d>& points);
std::vector<Eigen::Vector2d> pointsFrom(const nlohmann::json& j);

nlohmann::json jsonPose(const Pose2D& p);
Pose2D poseFrom(const nlohmann::json& j);

// Runs `read`, a reader of a JSON document in these forms, and turns what a malformed document
// makes it throw (FormatError, nlohmann's json::exception, InvalidArgumentError for a value out
// of range) into a FormatError naming `source`.
template <class F>
auto readingJson(const std::string& source, F&& read) {
  try {
    return read();
  } catch (const FormatError& e) {
    throw FormatError(source, 0, e.what());
  } catch (const nlohmann::json::exception& e) {
    throw FormatError(source, 0, e.what());
  } catch (const InvalidArgumentError& e) {
    throw FormatError(source, 0, e.what());
  }
}

}  // namespace rgnav
