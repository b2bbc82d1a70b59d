// Conversions between Common.idl / Module.idl types and core types (see convert.h).
#include "clientlibs/common/convert.h"

#include <cmath>
#include <cstring>

namespace rgnav {

RGNav::Time toIdlTime(Timestamp t) {
  RGNav::Time out;
  const double sec = std::floor(t);
  out.sec = static_cast<CORBA::LongLong>(sec);
  out.nsec = static_cast<CORBA::ULong>(std::llround((t - sec) * 1e9));
  if (out.nsec >= 1000000000u) {
    out.sec += 1;
    out.nsec -= 1000000000u;
  }
  return out;
}

Timestamp fromIdl(const RGNav::Time& t) { return static_cast<double>(t.sec) + t.nsec * 1e-9; }

RGNav::Pose2D toIdl(const Pose2D& p) { return RGNav::Pose2D{p.x, p.y, p.theta}; }
Pose2D fromIdl(const RGNav::Pose2D& p) { return Pose2D{p.x, p.y, p.theta}; }

RGNav::LaserScan toIdl(const LaserScan& s) {
  RGNav::LaserScan out;
  out.id = s.id;
  out.stamp = toIdlTime(s.stamp);
  out.odometry = toIdl(s.odometry);
  out.sensorPose = toIdl(s.sensorPose);
  out.startAngle = s.startAngle;
  out.angleIncrement = s.angleIncrement;
  out.maxRange = s.maxRange;
  out.ranges.length(static_cast<CORBA::ULong>(s.ranges.size()));
  if (!s.ranges.empty()) std::memcpy(out.ranges.get_buffer(), s.ranges.data(), s.ranges.size() * sizeof(float));
  return out;
}

LaserScan fromIdl(const RGNav::LaserScan& s) {
  LaserScan out;
  out.id = s.id;
  out.stamp = fromIdl(s.stamp);
  out.odometry = fromIdl(s.odometry);
  out.sensorPose = fromIdl(s.sensorPose);
  out.startAngle = s.startAngle;
  out.angleIncrement = s.angleIncrement;
  out.maxRange = s.maxRange;
  out.ranges.assign(s.ranges.get_buffer(), s.ranges.get_buffer() + s.ranges.length());
  return out;
}

RGNav::Odometry toIdl(const OdometryReading& o) {
  return RGNav::Odometry{o.id, toIdlTime(o.stamp), toIdl(o.pose), o.translationalVelocity, o.rotationalVelocity};
}

OdometryReading fromIdl(const RGNav::Odometry& o) {
  return OdometryReading{o.id, fromIdl(o.stamp), fromIdl(o.pose), o.translationalVelocity, o.rotationalVelocity};
}

namespace {
RGNav::ModuleState toIdl(ModuleRunState s) {
  switch (s) {
    case ModuleRunState::Starting: return RGNav::MODULE_STARTING;
    case ModuleRunState::Running: return RGNav::MODULE_RUNNING;
    case ModuleRunState::Degraded: return RGNav::MODULE_DEGRADED;
    case ModuleRunState::Stopping: return RGNav::MODULE_STOPPING;
  }
  return RGNav::MODULE_DEGRADED;
}

ModuleRunState fromIdl(RGNav::ModuleState s) {
  switch (s) {
    case RGNav::MODULE_STARTING: return ModuleRunState::Starting;
    case RGNav::MODULE_RUNNING: return ModuleRunState::Running;
    case RGNav::MODULE_DEGRADED: return ModuleRunState::Degraded;
    case RGNav::MODULE_STOPPING: return ModuleRunState::Stopping;
    default: return ModuleRunState::Degraded;
  }
}
}  // namespace

RGNav::ModuleStatus toIdl(const ModuleStatusInfo& s) {
  RGNav::ModuleStatus out;
  out.name = s.name.c_str();
  out.state = toIdl(s.state);
  out.pid = s.pid;
  out.uptimeSeconds = s.uptimeSeconds;
  out.counters.length(static_cast<CORBA::ULong>(s.counters.size()));
  CORBA::ULong i = 0;
  for (const auto& [name, value] : s.counters) {
    out.counters[i].name = name.c_str();
    out.counters[i].value = value;
    ++i;
  }
  out.lastError = s.lastError.c_str();
  return out;
}

ModuleStatusInfo fromIdl(const RGNav::ModuleStatus& s) {
  ModuleStatusInfo out;
  out.name = s.name.in();
  out.state = fromIdl(s.state);
  out.pid = s.pid;
  out.uptimeSeconds = s.uptimeSeconds;
  for (CORBA::ULong i = 0; i < s.counters.length(); ++i) out.counters[s.counters[i].name.in()] = s.counters[i].value;
  out.lastError = s.lastError.in();
  return out;
}

const char* toString(ModuleRunState state) {
  switch (state) {
    case ModuleRunState::Starting: return "starting";
    case ModuleRunState::Running: return "running";
    case ModuleRunState::Degraded: return "degraded";
    case ModuleRunState::Stopping: return "stopping";
  }
  return "unknown";
}

}  // namespace rgnav
