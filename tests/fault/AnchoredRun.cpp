// The replayed run's scans with their anchored corrected poses, and the kernel checkpoint of its
// map (see AnchoredRun.h).
#include "tests/fault/AnchoredRun.h"

#include "core/common/Errors.h"
#include "core/gateways/classify/HmmModelFile.h"
#include "core/logs/OpenLog.h"
#include "core/rgmap/kernel/RgMapCodec.h"
#include "tests/eval/localization/StampedPoses.h"
#include "tests/eval/rooms/MappingPipeline.h"

namespace rgnav::testing {

AnchoredRun anchoredRun(const std::string& log, const std::string& corrected, const std::string& models,
                        std::size_t maxScans) {
  const std::vector<LaserScan> scans = readLaserScans(log);
  const PoseMatch match = matchByStamp(scans, readScanPoses(corrected), 0.0, 0.001);
  if (match.matched != scans.size())
    throw InvalidArgumentError(corrected + ": only " + std::to_string(match.matched) + " of " +
                               std::to_string(scans.size()) + " scans have a corrected pose within 1 ms");
  // anchor ∘ corrected(first) = odometry(first)
  const Pose2D anchor = compose(scans.front().odometry, inverse(*match.poses.front()));
  AnchoredRun run;
  MappingPipeline pipeline(shippedPipelineConfig(), loadHmmModels(models));
  for (std::size_t i = 0; i < scans.size(); ++i) {
    const Pose2D truth = compose(anchor, *match.poses[i]);
    if (maxScans == 0 || i < maxScans) run.scans.push_back({scans[i].id, scans[i].odometry, truth});
    pipeline.addScanAt(scans[i], truth);
  }
  pipeline.finish();
  const RgMapState& state = pipeline.kernel().state();
  run.kernelState = serializeRgMap(state);
  run.kernelJournal = scanJournalLines(state);
  run.regions = state.regions.size();
  return run;
}

}  // namespace rgnav::testing
