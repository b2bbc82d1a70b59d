// The office RG map made in process with true poses (see OfficeRgMap.h).
#include "tests/eval/crowd/OfficeRgMap.h"

#include <filesystem>
#include <optional>

#include "core/common/AtomicFile.h"
#include "core/gateways/classify/HmmModelFile.h"
#include "core/rgmap/kernel/RgMapCodec.h"
#include "tests/eval/rooms/MappingRun.h"

namespace rgnav {

RgMapState mapWorldWithTruePoses(const LoadedWorld& world, const std::string& models) {
  if (!world.truth) throw InvalidArgumentError("the world has no ground-truth rooms to tour");
  std::optional<HmmClassifier> classifier;
  if (!models.empty() && std::filesystem::exists(models)) classifier = loadHmmModels(models);
  MappingRunSetup setup;
  setup.pipeline = shippedPipelineConfig();
  setup.truePoses = true;
  std::optional<RgMapState> state;
  setup.atEnd = [&](const RgMappingKernel& kernel) { state = kernel.state(); };
  mapRoomTour(world.grid, *world.truth, setup, classifier);
  return std::move(*state);
}

void writeKernelCheckpoint(const RgMapState& state, const std::string& stateDir) {
  std::filesystem::create_directories(stateDir);
  writeFileAtomically(stateDir + "/rgmap.state", serializeRgMap(state));
  writeFileAtomically(stateDir + "/rgmap.state.scans", scanJournalLines(state));
}

}  // namespace rgnav
