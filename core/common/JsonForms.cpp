// JSON forms of numbers, points and poses (see JsonForms.h).
#include "core/common/JsonForms.h"

#include <cmath>
#include <limits>

#include "core/common/Errors.h"

namespace rgnav {

using nlohmann::json;

json jsonNumber(double v) {
  if (std::isnan(v)) return nullptr;
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return v;
}

double numberFrom(const json& j) {
  if (j.is_null()) return std::numeric_limits<double>::quiet_NaN();
  if (j.is_string()) {
    if (j == "inf") return std::numeric_limits<double>::infinity();
    if (j == "-inf") return -std::numeric_limits<double>::infinity();
  }
  if (!j.is_number()) throw FormatError("<checkpoint>", 0, "not a number: " + j.dump());
  return j.get<double>();
}

json jsonPoint(const Eigen::Vector2d& p) { return json::array({jsonNumber(p.x()), jsonNumber(p.y())}); }

Eigen::Vector2d pointFrom(const json& j) {
  if (!j.is_array() || j.size() != 2) throw FormatError("<checkpoint>", 0, "not a point: " + j.dump());
  return {numberFrom(j[0]), numberFrom(j[1])};
}

json jsonPoints(const std::vector<Eigen::Vector2d>& points) {
  json out = json::array();
  for (const Eigen::Vector2d& p : points) out.push_back(jsonPoint(p));
  return out;
}

std::vector<Eigen::Vector2d> pointsFrom(const json& j) {
  if (!j.is_array()) throw FormatError("<checkpoint>", 0, "not a list of points: " + j.dump());
  std::vector<Eigen::Vector2d> out;
  for (const json& p : j) out.push_back(pointFrom(p));
  return out;
}

json jsonPose(const Pose2D& p) { return json::array({jsonNumber(p.x), jsonNumber(p.y), jsonNumber(p.theta)}); }

Pose2D poseFrom(const json& j) {
  if (!j.is_array() || j.size() != 3) throw FormatError("<checkpoint>", 0, "not a pose: " + j.dump());
  return {numberFrom(j[0]), numberFrom(j[1]), numberFrom(j[2])};
}

}  // namespace rgnav
