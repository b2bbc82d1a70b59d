// Conversions between Localization.idl types and the region MCL's (see convert.h).
#include "clientlibs/localization/convert.h"

#include "clientlibs/common/convert.h"

namespace rgnav {
namespace {

void toIdl(const Eigen::Matrix3d& m, RGNav::Matrix3 out) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out[3 * r + c] = m(r, c);
}

Eigen::Matrix3d fromIdl(const RGNav::Matrix3 m) {
  Eigen::Matrix3d out;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out(r, c) = m[3 * r + c];
  return out;
}

}  // namespace

RGNav::LocalizationEstimate toIdl(const ScanEstimate& s) {
  const PoseEstimate& e = s.estimate;
  RGNav::LocalizationEstimate out;
  out.scanId = s.scanId;
  out.updateScanId = e.scanId;
  out.region = e.region.value();
  out.mapPose = toIdl(e.mapPose);
  out.regionPose = toIdl(e.regionPose);
  toIdl(e.covariance, out.covariance);
  out.bestParticle = toIdl(e.bestParticle);
  out.clusterWeight = e.clusterWeight;
  out.particles = static_cast<CORBA::ULong>(e.particles);
  out.fitPerBeam = e.fitPerBeam;
  return out;
}

ScanEstimate fromIdl(const RGNav::LocalizationEstimate& s) {
  ScanEstimate out;
  out.scanId = s.scanId;
  PoseEstimate& e = out.estimate;
  e.scanId = s.updateScanId;
  e.region = RegionId(s.region);
  e.mapPose = fromIdl(s.mapPose);
  e.regionPose = fromIdl(s.regionPose);
  e.covariance = fromIdl(s.covariance);
  e.bestParticle = fromIdl(s.bestParticle);
  e.clusterWeight = s.clusterWeight;
  e.particles = s.particles;
  e.fitPerBeam = s.fitPerBeam;
  return out;
}

RGNav::LocalizationParticle toIdl(const ParticleView& p) {
  return {p.particle.region.value(), toIdl(p.particle.pose), toIdl(p.mapPose), p.particle.weight};
}

ParticleView fromIdl(const RGNav::LocalizationParticle& p) {
  return {{RegionId(p.region), fromIdl(p.regionPose), p.weight}, fromIdl(p.mapPose)};
}

RGNav::ParticleSnapshot toIdl(const ParticleSnapshotView& s) {
  RGNav::ParticleSnapshot out;
  out.scanId = s.scanId;
  out.total = static_cast<CORBA::ULong>(s.total);
  out.particles = toIdlSeq<RGNav::LocalizationParticleSeq>(s.particles, [](const ParticleView& p) { return toIdl(p); });
  return out;
}

ParticleSnapshotView fromIdl(const RGNav::ParticleSnapshot& s) {
  return {s.scanId, s.total,
          fromIdlSeq<std::vector<ParticleView>>(s.particles, [](const RGNav::LocalizationParticle& p) { return fromIdl(p); })};
}

RGNav::LocalizationState toIdl(const LocalizationStateView& s) {
  return {s.initialised, static_cast<CORBA::ULong>(s.mapRegions), s.mapRevision, s.updates, s.lastScan,
          s.traversalsReported};
}

LocalizationStateView fromIdl(const RGNav::LocalizationState& s) {
  return {static_cast<bool>(s.initialised), s.mapRegions, s.mapRevision, s.updates, s.lastScan, s.traversalsReported};
}

RGNav::PoseSigma toIdlSigma(const Eigen::Vector3d& sigma) { return {sigma.x(), sigma.y(), sigma.z()}; }

Eigen::Vector3d fromIdl(const RGNav::PoseSigma& sigma) { return {sigma.x, sigma.y, sigma.theta}; }

}  // namespace rgnav
