// Relations file parsing, stamp matching and derivation from a reference trajectory.
#include "core/slam/eval/Relations.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/common/Errors.h"

namespace rgnav {

std::vector<Relation> readRelations(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw FileError("cannot open relations file " + path);
  std::vector<Relation> relations;
  std::string line;
  std::size_t lineNumber = 0;
  while (std::getline(in, line)) {
    ++lineNumber;
    const auto start = line.find_first_not_of(" \t\r");
    if (start == std::string::npos || line[start] == '#') continue;
    std::istringstream fields(line);
    double v[8];
    for (double& value : v)
      if (!(fields >> value) || !std::isfinite(value))
        throw FormatError(path, lineNumber, "expected 8 numbers: t1 t2 dx dy dz droll dpitch dyaw");
    relations.push_back({v[0], v[1], {v[2], v[3], normalizeAngle(v[7])}});
  }
  if (in.bad()) throw FileError("cannot read relations file " + path);
  return relations;
}

std::vector<ScanRelation> matchRelations(std::span<const Relation> relations, std::span<const StampedScan> scans,
                                         double stampOffset, double tolerance) {
  std::vector<StampedScan> sorted(scans.begin(), scans.end());
  std::sort(sorted.begin(), sorted.end(), [](const StampedScan& a, const StampedScan& b) { return a.stamp < b.stamp; });
  const auto nearest = [&](Timestamp stamp) -> const StampedScan* {
    const auto it = std::lower_bound(sorted.begin(), sorted.end(), stamp,
                                     [](const StampedScan& s, Timestamp t) { return s.stamp < t; });
    const StampedScan* best = nullptr;
    if (it != sorted.end()) best = &*it;
    if (it != sorted.begin() && (best == nullptr || stamp - std::prev(it)->stamp < best->stamp - stamp)) best = &*std::prev(it);
    return best != nullptr && std::abs(best->stamp - stamp) <= tolerance ? best : nullptr;
  };
  std::vector<ScanRelation> matched;
  for (const Relation& r : relations) {
    const StampedScan* a = nearest(r.first - stampOffset);
    const StampedScan* b = nearest(r.second - stampOffset);
    if (a != nullptr && b != nullptr && a->id != b->id) matched.push_back({a->id, b->id, r.relative});
  }
  return matched;
}

std::vector<ScanRelation> relationsFromTrajectory(std::span<const TrajectoryPose> reference,
                                                  const DerivedRelationsConfig& config) {
  std::vector<const TrajectoryPose*> samples;
  for (const TrajectoryPose& p : reference) {
    if (!samples.empty()) {
      const Pose2D motion = between(samples.back()->pose, p.pose);
      if (std::hypot(motion.x, motion.y) < config.step && std::abs(motion.theta) < config.step) continue;
    }
    samples.push_back(&p);
  }
  std::vector<ScanRelation> relations;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const TrajectoryPose& s = *samples[i];
    if (i + 1 < samples.size()) relations.push_back({s.id, samples[i + 1]->id, between(s.pose, samples[i + 1]->pose)});
    const TrajectoryPose* revisit = nullptr;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < i && samples[j]->stamp <= s.stamp - config.revisitAge; ++j) {
      const Pose2D& q = samples[j]->pose;
      const double distance = std::hypot(q.x - s.pose.x, q.y - s.pose.y);
      if (distance <= config.revisitDistance && distance < best &&
          std::abs(normalizeAngle(q.theta - s.pose.theta)) <= config.revisitRotation) {
        best = distance;
        revisit = samples[j];
      }
    }
    if (revisit != nullptr) relations.push_back({revisit->id, s.id, between(revisit->pose, s.pose)});
  }
  return relations;
}

}  // namespace rgnav
