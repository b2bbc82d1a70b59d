// Rendering, observing, tracking and labelling one scenario; see ScenarioSequences.h.
#include "tests/eval/crossings/ScenarioSequences.h"

#include <random>

#include "core/sim/world/Raycaster.h"

namespace rgnav {

ScenarioSequences scenarioSequences(const ScenarioSpec& spec, const CrossingsSetup& setup) {
  const HallwayScenario scenario = buildScenario(spec, setup.scenarios);
  const Raycaster raycaster(scenario.world);
  const LaserModel laser(setup.laser);
  VlmObserverParams observerParams = setup.observer;
  observerParams.hypotheses.hallwayWidthM = spec.environment.width;
  const VlmObserver observer(observerParams);
  std::mt19937_64 rng(spec.seed ^ 0x9e3779b97f4a7c15ULL);
  const Pose2D gateway{scenario.gatewayCentre.x, scenario.gatewayCentre.y, 0.0};

  ScenarioSequences result;
  result.approaches = scenario.approaches.size();
  for (const Approach& approach : scenario.approaches) {
    HypothesisTracker tracker(setup.tracker);
    for (const LabelledPose& labelled : approach.poses) {
      const Pose2D pose = compose(gateway, labelled.pose);
      const LaserScan scan = laser.simulate(pose, pose, 0, 0.0, raycaster, rng);
      tracker.update(scan.sensorPose, observer.observe(scan),
                     [&](const GatewayPoints& points) { return observer.observeAt(points, scan); });
    }
    tracker.flush();
    for (LabelledTrack& t : labelApproach(tracker.takeFinished(), spec.gatewayClass, spec.environment.width,
                                          setup.labels))
      result.tracks.push_back(std::move(t));
  }
  return result;
}

}  // namespace rgnav
