// Greedy particle clustering and the clusters' weighted means (ParticleClusters.h).
#include "core/nav/localization/ParticleClusters.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

struct Accumulator {
  std::size_t seed = 0;
  double weight = 0.0, sx = 0.0, sy = 0.0, sc = 0.0, ss = 0.0;
  std::vector<std::size_t> members;
};

}  // namespace

std::vector<ParticleCluster> clusterParticles(std::span<const Particle> particles, std::span<const Pose2D> mapPoses,
                                              double radiusM, double angleRad) {
  if (particles.size() != mapPoses.size()) throw InvalidArgumentError("clusterParticles: one map pose per particle");
  std::vector<std::size_t> order(particles.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return particles[a].weight > particles[b].weight; });
  std::vector<Accumulator> clusters;
  const double r2 = radiusM * radiusM;
  for (const std::size_t i : order) {
    const Pose2D& p = mapPoses[i];
    auto joined = std::find_if(clusters.begin(), clusters.end(), [&](const Accumulator& c) {
      const Pose2D& s = mapPoses[c.seed];
      const double dx = p.x - s.x, dy = p.y - s.y;
      return dx * dx + dy * dy <= r2 && std::abs(normalizeAngle(p.theta - s.theta)) <= angleRad;
    });
    if (joined == clusters.end()) {
      clusters.push_back({});
      clusters.back().seed = i;
      joined = std::prev(clusters.end());
    }
    const double w = particles[i].weight;
    joined->weight += w;
    joined->sx += w * p.x;
    joined->sy += w * p.y;
    joined->sc += w * std::cos(p.theta);
    joined->ss += w * std::sin(p.theta);
    joined->members.push_back(i);
  }
  std::vector<ParticleCluster> result;
  result.reserve(clusters.size());
  for (const Accumulator& c : clusters) {
    ParticleCluster out;
    out.region = particles[c.seed].region;
    out.weight = c.weight;
    out.members = c.members.size();
    if (c.weight > 0.0) {
      out.mean = {c.sx / c.weight, c.sy / c.weight, std::atan2(c.ss, c.sc)};
      for (const std::size_t i : c.members) {
        const Eigen::Vector3d d(mapPoses[i].x - out.mean.x, mapPoses[i].y - out.mean.y,
                                normalizeAngle(mapPoses[i].theta - out.mean.theta));
        out.covariance += particles[i].weight / c.weight * d * d.transpose();
      }
    } else {
      out.mean = mapPoses[c.seed];
    }
    result.push_back(out);
  }
  std::stable_sort(result.begin(), result.end(), [](const ParticleCluster& a, const ParticleCluster& b) { return a.weight > b.weight; });
  return result;
}

}  // namespace rgnav
