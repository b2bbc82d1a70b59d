// The argument checks of every servant (see WireChecks.h).
#include "servers/common/WireChecks.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace rgnav::wire {

void refuse(const char* field, const std::string& why) {
  throw RGNav::InvalidArgument(field, (std::string(field) + " " + why).c_str());
}

void requireFinite(double value, const char* field) {
  if (!std::isfinite(value)) refuse(field, "must be a finite number, got " + std::to_string(value));
}

void requireFinite(const RGNav::Point2D& point, const char* field) {
  if (!std::isfinite(point.x) || !std::isfinite(point.y)) refuse(field, "must have finite coordinates");
}

void requireFinite(const RGNav::Pose2D& pose, const char* field) {
  if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.theta))
    refuse(field, "must have finite coordinates and angle");
}

void requireValid(const RGNav::Time& stamp, const char* field) {
  if (stamp.nsec >= 1'000'000'000u) refuse(field, "must have nsec below 10^9, got " + std::to_string(stamp.nsec));
}

void requireId(std::uint64_t id, const char* field) {
  if (id == 0) refuse(field, "must be an ID (IDs start at 1), got 0");
}

void requireIdRange(std::uint64_t first, std::uint64_t last, const char* firstField, const char* lastField) {
  requireId(first, firstField);
  if (last < first) refuse(lastField, std::string("must not be before ") + firstField);
}

std::size_t cappedCount(std::uint32_t requested, std::uint32_t cap, const char* field) {
  if (requested == 0) refuse(field, "must be at least 1");
  return std::min(requested, cap);
}

std::string checkedName(const char* name, const char* field, bool mayBeEmpty, std::size_t maxLength) {
  const std::size_t length = std::strlen(name);
  if (length == 0 && !mayBeEmpty) refuse(field, "must not be empty");
  if (length > maxLength)
    refuse(field, "is " + std::to_string(length) + " bytes long, more than " + std::to_string(maxLength));
  for (std::size_t i = 0; i < length; ++i)
    if (static_cast<unsigned char>(name[i]) < 0x20 || name[i] == 0x7f) refuse(field, "must not contain control characters");
  return std::string(name, length);
}

}  // namespace rgnav::wire
