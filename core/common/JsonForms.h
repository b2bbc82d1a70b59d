// JsonForms: how the checkpoints and exports write numbers, points and poses as JSON
// (nlohmann::json): numbers in the shortest form that reads back to the same double, non-finite
// numbers as "inf", "-inf" and null (NaN), points as [x, y], poses as [x, y, theta]. Reading
// anything else throws FormatError (file "<checkpoint>").
#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/common/Pose2D.h"

namespace rgnav {

nlohmann::json jsonNumber(double v);
double numberFrom(const nlohmann::json& j);

nlohmann::json jsonPoint(const Eigen::Vector2d& p);
Eigen::Vector2d pointFrom(const nlohmann::json& j);

nlohmann::json jsonPoints(const std::vector<Eigen::Vector2d>& points);
std::vector<Eigen::Vector2d> pointsFrom(const nlohmann::json& j);

nlohmann::json jsonPose(const Pose2D& p);
Pose2D poseFrom(const nlohmann::json& j);

}  // namespace rgnav
