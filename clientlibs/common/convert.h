// Conversions between the IDL types of Common.idl / Module.idl and their core counterparts.
// The only place (with the per-module convert files) where IDL and core types meet.
#pragma once

#include "Common.hh"
#include "Module.hh"
#include "clientlibs/common/ModuleStatusInfo.h"
#include "core/common/SensorData.h"

namespace rgnav {

RGNav::Time toIdlTime(Timestamp t);
Timestamp fromIdl(const RGNav::Time& t);

RGNav::Pose2D toIdl(const Pose2D& p);
Pose2D fromIdl(const RGNav::Pose2D& p);

RGNav::LaserScan toIdl(const LaserScan& s);
LaserScan fromIdl(const RGNav::LaserScan& s);

RGNav::Odometry toIdl(const OdometryReading& o);
OdometryReading fromIdl(const RGNav::Odometry& o);

RGNav::ModuleStatus toIdl(const ModuleStatusInfo& s);
ModuleStatusInfo fromIdl(const RGNav::ModuleStatus& s);

// Copies a core vector into an IDL sequence (and back) element by element with `convert`
// (pass a lambda calling toIdl / fromIdl where the element's overload is visible).
template <class Seq, class Vec, class Convert>
Seq toIdlSeq(const Vec& items, Convert convert) {
  Seq seq;
  seq.length(static_cast<CORBA::ULong>(items.size()));
  CORBA::ULong i = 0;
  for (const auto& item : items) seq[i++] = convert(item);
  return seq;
}

template <class Vec, class Seq, class Convert>
Vec fromIdlSeq(const Seq& seq, Convert convert) {
  Vec items;
  items.reserve(seq.length());
  for (CORBA::ULong i = 0; i < seq.length(); ++i) items.push_back(convert(seq[i]));
  return items;
}

}  // namespace rgnav
