// Particles spread uniformly over the map's freespace (see FreespaceSeeding.h).
#include "servers/localization/FreespaceSeeding.h"

#include <numbers>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

struct FreeCell {
  RegionId region;
  int col = 0, row = 0;
};

}  // namespace

std::vector<Particle> uniformFreespaceParticles(const LocalizationMap& map, std::size_t count, std::mt19937_64& rng) {
  std::vector<FreeCell> cells;
  for (const RegionId id : map.regionIds()) {
    const FreespaceBitmap& free = map.region(id).freespace;
    for (int row = 0; row < free.height; ++row)
      for (int col = 0; col < free.width; ++col)
        if (free.isFree(col, row)) cells.push_back({id, col, row});
  }
  if (cells.empty()) throw NotAvailableError("no region of the map has a free cell to place particles in");
  std::uniform_int_distribution<std::size_t> pick(0, cells.size() - 1);
  std::uniform_real_distribution<double> within(-0.5, 0.5);
  std::uniform_real_distribution<double> heading(-std::numbers::pi, std::numbers::pi);
  std::vector<Particle> particles;
  particles.reserve(count);
  const double weight = 1.0 / static_cast<double>(std::max<std::size_t>(count, 1));
  for (std::size_t i = 0; i < count; ++i) {
    const FreeCell& c = cells[pick(rng)];
    const FreespaceBitmap& free = map.region(c.region).freespace;
    const Eigen::Vector2d centre = free.cellCenter(c.col, c.row);
    particles.push_back({c.region,
                         {centre.x() + within(rng) * free.resolutionM, centre.y() + within(rng) * free.resolutionM,
                          heading(rng)},
                         weight});
  }
  return particles;
}

}  // namespace rgnav
