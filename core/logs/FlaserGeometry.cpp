// FlaserGeometry: the beam-count rule documented for the CARMEN logs (data/laser/SOURCES.md).
#include "core/logs/FlaserGeometry.h"

namespace rgnav {

double flaserAngleIncrement(std::size_t beams) {
  if (beams == 180 || beams == 360) {
    return M_PI / static_cast<double>(beams);
  }
  if (beams < 2) {
    return 0.0;
  }
  return M_PI / static_cast<double>(beams - 1);
}

}  // namespace rgnav
