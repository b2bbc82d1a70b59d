// GatewayDetectionService: the GatewayDetection module's work behind its servant (thesis 5.2):
// follows the Laser module's raw scans by ID ("the GDM continuously acquires raw laser
// readings"), runs the GatewayDetector on every scan, keeps the buffer of gateway events for
// consumers and checkpoints detector and buffer atomically at most once per checkpointIntervalS
// (less often as they grow) while detecting and at the end (CheckpointPacer.h); one that cannot
// be written degrades the module and is retried with backoff (CheckpointRetry.h). After a restart
// it reloads the checkpoint and goes on after the last scan it holds, so events keep their IDs
// and nothing is lost: the scans it sees again give the same events under the same IDs.
// Where we differ: gateways are tracked in the odometry frame of the scans, not with the
// ScanMapper's corrected poses. A gateway is tracked over a few metres of driving, where odometry
// is good; corrected poses change whenever the pose graph is optimised, and how far the
// ScanMapper is when a pose is fetched depends on timing, so detection on them would not give
// the same gateways after a restart. A consumer places a gateway into the map frame with the
// corrected pose of its lastScan (ScanMapper::odomToMap) - with the newest correction, which is
// better than the one at detection time.
#pragma once

#include <mutex>
#include <string>

#include "core/gateways/detection/GatewayEventBatch.h"
#include "clientlibs/laser/LaserClient.h"
#include "core/common/DataBuffer.h"
#include "core/gateways/detection/GatewayDetector.h"
#include "servers/common/CheckpointPacer.h"
#include "servers/common/CheckpointRetry.h"
#include "servers/common/InputFollower.h"

namespace rgnav {

struct GatewayDetectionServiceOptions {
  std::string checkpointFile;          // empty: no checkpoints
  std::size_t eventCapacity = 100000;  // events held for consumers
  std::uint32_t fetchBatch = 100;      // scans asked from the Laser module per call
  double checkpointIntervalS = 1.0;    // at least this long between checkpoints while detecting (CheckpointPacer.h)
};

class GatewayDetectionService {
 public:
  // Loads the checkpoint if there is one (FormatError if it is damaged: the module then fails at
  // start and the operator decides). Does not contact other modules yet.
  GatewayDetectionService(const GatewayDetectorConfig& config, std::optional<HmmClassifier> classifier,
                          const ClientSettings& laserSettings, const std::string& laserObject,
                          GatewayDetectionServiceOptions options, ModuleHealth& health);
  ~GatewayDetectionService();

  void start();
  void stop();

  GatewayEventBatch eventsSince(GatewayEventId afterId, std::size_t maxCount);
  std::vector<GatewayRecord> gateways();
  // NotAvailableError for an ID not (yet) given.
  GatewayRecord gateway(DetectorGatewayId id);
  DataId lastProcessedScan();
  bool detectsHallways();

 private:
  bool followOnce();  // false when there was nothing new
  void checkpoint();  // under lock
  // A scan the detector failed on kAttemptsPerRecord times (InputFollower.h) is left out.
  std::string skipFailingScan();

  GatewayDetectionServiceOptions options_;
  LaserClient laser_;
  ModuleHealth& health_;
  std::mutex mutex_;
  std::unique_ptr<GatewayDetector> detector_;
  DataBuffer<GatewayEvent> events_;
  CheckpointPacer pacer_;
  CheckpointRetry retry_;  // after a failed checkpoint
  bool finished_ = false;
  DataId processing_ = 0;  // the scan being detected in
  DataId skipScan_ = 0;    // the scan left out
  InputFollower follower_;  // last: it stops before the rest goes
};

}  // namespace rgnav
