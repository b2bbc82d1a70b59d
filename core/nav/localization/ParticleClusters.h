// ParticleClusters: the particle set grouped into clusters of nearby poses, and the pose
// estimate of the heaviest one (the issue asks for the mean of the best cluster; the thesis 5.3
// took the best particle: both are reported, RegionMcl.h). Clustering is greedy: particles in
// descending weight order, each joins the first cluster whose seed (its heaviest particle) lies
// within MclConfig::clusterRadiusM and clusterAngleRad in the map frame, else seeds a new one.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <span>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/nav/localization/Particle.h"

namespace rgnav {

struct ParticleCluster {
  RegionId region;         // the region of the cluster's heaviest particle
  Pose2D mean;             // weighted mean, map frame (heading: circular mean)
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  // x, y, theta (map frame)
  double weight = 0.0;     // the members' weight sum
  std::size_t members = 0;
};

// `mapPoses[i]` is particles[i]'s pose in the map frame. Heaviest cluster first.
std::vector<ParticleCluster> clusterParticles(std::span<const Particle> particles, std::span<const Pose2D> mapPoses,
                                              double radiusM, double angleRad);

}  // namespace rgnav
