// ParticleSetCodec: the Localization module's checkpoint: the particle set as of a filter update
// and the scan of that update, so that a restarted module resumes the filter where it was (it
// takes that scan again as its odometry reference, then the scans after it). The text is JSON
// ({"format": "rgnav-particles", "version": 1, "scan", "particles": [[region, [x, y, theta],
// weight], ...]}) with every number written so that it reads back to exactly the same double
// (JsonForms.h); the module writes it atomically (AtomicFile.h).
#pragma once

#include <string>
#include <vector>

#include "core/common/SensorData.h"
#include "core/nav/localization/Particle.h"

namespace rgnav {

struct ParticleSetCheckpoint {
  DataId scanId = 0;  // the scan of the filter update the particles are of
  std::vector<Particle> particles;

  friend bool operator==(const ParticleSetCheckpoint&, const ParticleSetCheckpoint&) = default;
};

std::string serializeParticles(const ParticleSetCheckpoint& checkpoint);
// Throws FormatError naming `source` for a text that is not such a checkpoint (another format or
// version, a missing or malformed field, a particle without a region or with a non-finite or
// negative number).
ParticleSetCheckpoint deserializeParticles(const std::string& text, const std::string& source);

}  // namespace rgnav
