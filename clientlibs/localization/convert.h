// Conversions between Localization.idl types and the region MCL's plain types (RegionMcl.h,
// LocalizationViews.h): estimates, particles, particle snapshots, the module's state and the
// initial guess's sigma. The only place where the two meet.
#pragma once

#include <Eigen/Core>

#include "Localization.hh"
#include "clientlibs/localization/LocalizationViews.h"

namespace rgnav {

RGNav::LocalizationEstimate toIdl(const ScanEstimate& estimate);
ScanEstimate fromIdl(const RGNav::LocalizationEstimate& estimate);
RGNav::LocalizationParticle toIdl(const ParticleView& particle);
ParticleView fromIdl(const RGNav::LocalizationParticle& particle);
RGNav::ParticleSnapshot toIdl(const ParticleSnapshotView& snapshot);
ParticleSnapshotView fromIdl(const RGNav::ParticleSnapshot& snapshot);
RGNav::LocalizationState toIdl(const LocalizationStateView& state);
LocalizationStateView fromIdl(const RGNav::LocalizationState& state);
// Sigma (x, y in m, theta in rad).
RGNav::PoseSigma toIdlSigma(const Eigen::Vector3d& sigma);
Eigen::Vector3d fromIdl(const RGNav::PoseSigma& sigma);

}  // namespace rgnav
