// The particle set checkpoint as JSON (see ParticleSetCodec.h).
#include "core/nav/localization/ParticleSetCodec.h"

#include <cmath>

#include "core/common/JsonForms.h"

namespace rgnav {
namespace {

constexpr const char* kFormat = "rgnav-particles";
constexpr int kVersion = 1;

Particle particleFrom(const nlohmann::json& j) {
  if (!j.is_array() || j.size() != 3) throw FormatError("<checkpoint>", 0, "not a particle: " + j.dump());
  Particle p{j[0].get<RegionId>(), poseFrom(j[1]), numberFrom(j[2])};
  if (p.region.isNone()) throw FormatError("<checkpoint>", 0, "a particle without a region");
  if (!std::isfinite(p.pose.x) || !std::isfinite(p.pose.y) || !std::isfinite(p.pose.theta) ||
      !std::isfinite(p.weight) || p.weight < 0.0)
    throw FormatError("<checkpoint>", 0, "a particle with a non-finite or negative number: " + j.dump());
  return p;
}

}  // namespace

std::string serializeParticles(const ParticleSetCheckpoint& checkpoint) {
  nlohmann::json particles = nlohmann::json::array();
  for (const Particle& p : checkpoint.particles)
    particles.push_back({p.region, jsonPose(p.pose), jsonNumber(p.weight)});
  const nlohmann::json j{{"format", kFormat},
                         {"version", kVersion},
                         {"scan", checkpoint.scanId},
                         {"particles", std::move(particles)}};
  return j.dump() + "\n";
}

ParticleSetCheckpoint deserializeParticles(const std::string& text, const std::string& source) {
  return readingJson(source, [&] {
    const nlohmann::json j = nlohmann::json::parse(text);
    if (j.at("format") != kFormat) throw FormatError("<checkpoint>", 0, "not a particle set checkpoint");
    const int version = integerFrom(j.at("version"));
    if (version != kVersion) throw FormatError("<checkpoint>", 0, "unknown version " + std::to_string(version));
    ParticleSetCheckpoint out;
    out.scanId = integerFrom(j.at("scan"));
    const nlohmann::json& particles = j.at("particles");
    if (!particles.is_array()) throw FormatError("<checkpoint>", 0, "particles is not a list");
    for (const nlohmann::json& p : particles) out.particles.push_back(particleFrom(p));
    return out;
  });
}

}  // namespace rgnav
