// The producer side of "data by ID" (DESIGN.md) as the Laser and Base servers see it, whatever
// makes the data (a log playback, the simulator, a robot): scans and odometry by ID, and the
// base's velocity command. Implementations are thread-safe.
#pragma once

#include <string>

#include "core/common/DataBuffer.h"

namespace rgnav {

class LaserStream {
 public:
  virtual ~LaserStream() = default;
  // Scans with ID > afterId, at most maxCount; `consumer` names the caller ("" = anonymous).
  virtual DataBatch<LaserScan> scansSince(DataId afterId, std::size_t maxCount, const std::string& consumer) = 0;
  // InvalidArgumentError for ID 0, NotAvailableError for an ID not held.
  virtual LaserScan scan(DataId id) = 0;
  virtual DataId latestScanId() = 0;
  virtual DataId oldestScanId() = 0;
};

class BaseStream {
 public:
  virtual ~BaseStream() = default;
  virtual DataBatch<OdometryReading> odometrySince(DataId afterId, std::size_t maxCount, const std::string& consumer) = 0;
  // Interpolated; NotAvailableError outside the readings held.
  virtual OdometryReading odometryAt(Timestamp stamp) = 0;
  virtual DataId latestOdometryId() = 0;
  // NotSupportedError where the base cannot be driven; InvalidArgumentError for bad values.
  virtual void setVelocity(double translational, double rotational) = 0;
};

}  // namespace rgnav
