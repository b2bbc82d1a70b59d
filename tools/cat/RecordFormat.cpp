// Text forms of records for rgnav-cat (see RecordFormat.h).
#include "tools/cat/RecordFormat.h"

#include <cmath>
#include <cstdio>
#include <limits>

namespace rgnav {

std::string formatScan(const LaserScan& scan) {
  std::size_t valid = 0, noReturn = 0;
  float lo = std::numeric_limits<float>::infinity(), hi = 0.0f;
  for (float r : scan.ranges) {
    if (std::isinf(r)) ++noReturn;
    if (!std::isfinite(r)) continue;
    ++valid;
    lo = std::min(lo, r);
    hi = std::max(hi, r);
  }
  if (valid == 0) lo = 0.0f;
  char line[256];
  std::snprintf(line, sizeof line, "scan %llu %.6f %zu %zu %zu %.3f %.3f %.4f %.4f %.4f",
                static_cast<unsigned long long>(scan.id), scan.stamp, scan.ranges.size(), valid, noReturn, lo, hi,
                scan.odometry.x, scan.odometry.y, scan.odometry.theta);
  return line;
}

std::string formatOdometry(const OdometryReading& odometry) {
  char line[192];
  std::snprintf(line, sizeof line, "odom %llu %.6f %.4f %.4f %.4f %.4f %.4f", static_cast<unsigned long long>(odometry.id),
                odometry.stamp, odometry.pose.x, odometry.pose.y, odometry.pose.theta, odometry.translationalVelocity,
                odometry.rotationalVelocity);
  return line;
}

}  // namespace rgnav

namespace rgnav {

std::string formatCorrected(const CorrectedScan& scan) {
  char line[160];
  std::snprintf(line, sizeof line, "corrected %llu %.6f %.6f %.6f %.6f %d", static_cast<unsigned long long>(scan.scan.id),
                scan.scan.stamp, scan.corrected.x, scan.corrected.y, scan.corrected.theta, scan.keyframe ? 1 : 0);
  return line;
}

namespace {

const char* eventKindName(GatewayEventKind kind) {
  switch (kind) {
    case GatewayEventKind::Detected: return "detected";
    case GatewayEventKind::Updated: return "updated";
    case GatewayEventKind::Traversed: break;
  }
  return "traversed";
}

std::string pointList(const std::vector<Eigen::Vector2d>& points) {
  std::string out;
  char buffer[64];
  for (const Eigen::Vector2d& p : points) {
    std::snprintf(buffer, sizeof buffer, "%s%.3f,%.3f", out.empty() ? "" : ";", p.x(), p.y());
    out += buffer;
  }
  return out;
}

std::string gatewayFields(const GatewayRecord& g) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "%llu %s %.3f width=%.2f points=", static_cast<unsigned long long>(g.id.value()),
                g.label().c_str(), g.classes.front().probability, g.widthM);
  std::string out = buffer + pointList(g.gatewayPoints);
  std::snprintf(buffer, sizeof buffer, " seen=%llu-%llu", static_cast<unsigned long long>(g.firstScan),
                static_cast<unsigned long long>(g.lastScan));
  return out + buffer;
}

}  // namespace

std::string formatGatewayEvent(const GatewayEvent& e) {
  std::string out = "gateway " + std::to_string(e.id) + " scan=" + std::to_string(e.scanId) + " " +
                    eventKindName(e.kind) + " " + gatewayFields(e.gateway);
  if (e.kind != GatewayEventKind::Traversed) return out;
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, " from=%zu to=%zu at=%.3f,%.3f", e.traversal.fromSide, e.traversal.toSide,
                e.traversal.at.x(), e.traversal.at.y());
  return out + buffer;
}

std::string formatGateway(const GatewayRecord& g) {
  return gatewayFields(g) + " support=" + std::to_string(g.support) + " traversals=" + std::to_string(g.traversals);
}

}  // namespace rgnav
