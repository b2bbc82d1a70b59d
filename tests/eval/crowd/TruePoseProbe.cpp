// The true pose of the latest scan (see TruePoseProbe.h).
#include "tests/eval/crowd/TruePoseProbe.h"

namespace rgnav {

TruePoseProbe::TruePoseProbe(const ClientSettings& settings) : laser_(settings), truth_(settings) {}

TrueSample TruePoseProbe::latest() {
  const DataId id = laser_.latestId();
  if (id == 0) throw NotAvailableError("the simulator has no scan yet");
  return {id, truth_.truePose(id)};
}

}  // namespace rgnav
