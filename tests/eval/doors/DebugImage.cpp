// The door evaluation's debug picture (see DebugImage.h).
#include "tests/eval/doors/DebugImage.h"

#include <array>
#include <cmath>

#include "core/sim/world/PngIo.h"

namespace rgnav {
namespace {

constexpr int kScale = 3;
using Rgb = std::array<std::uint8_t, 3>;

class Canvas {
 public:
  explicit Canvas(const OccupancyGrid& world)
      : world_(world), image_(world.width() * kScale, world.height() * kScale, 255) {
    for (int row = 0; row < world.height(); ++row)
      for (int col = 0; col < world.width(); ++col)
        if (world.blocked({col, row})) fillCell(col, row, {90, 90, 90});
  }

  void line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Rgb& colour) {
    const double pixel = world_.resolution() / kScale;
    const int steps = 1 + static_cast<int>((b - a).norm() / (pixel / 2.0));
    for (int i = 0; i <= steps; ++i) {
      const Eigen::Vector2d p = a + (b - a) * (double(i) / steps);
      const int x = static_cast<int>(std::floor((p.x() - world_.origin().x) / pixel));
      const int y = image_.height() - 1 - static_cast<int>(std::floor((p.y() - world_.origin().y) / pixel));
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) set(x + dx, y + dy, colour);
    }
  }

  const RgbImage& image() const { return image_; }

 private:
  void fillCell(int col, int row, const Rgb& colour) {
    for (int dy = 0; dy < kScale; ++dy)
      for (int dx = 0; dx < kScale; ++dx) set(col * kScale + dx, (world_.height() - 1 - row) * kScale + dy, colour);
  }
  void set(int x, int y, const Rgb& colour) {
    if (x < 0 || y < 0 || x >= image_.width() || y >= image_.height()) return;
    for (int c = 0; c < 3; ++c) image_.set(x, y, colour[static_cast<std::size_t>(c)], c);
  }

  const OccupancyGrid& world_;
  RgbImage image_;
};

}  // namespace

void writeDoorImage(const std::string& path, const OccupancyGrid& world, const std::vector<TruthDoor>& doors,
                    const std::vector<TrackedGateway>& gateways, const DoorMatch& match) {
  Canvas canvas(world);
  for (std::size_t d = 0; d < doors.size(); ++d) {
    const Rgb colour = doors[d].exclusion != DoorExclusion::kNone ? Rgb{255, 160, 0}
                       : match.detectionOfDoor[d] >= 0        ? Rgb{0, 190, 0}
                                                              : Rgb{230, 0, 0};
    canvas.line({doors[d].line.a.x, doors[d].line.a.y}, {doors[d].line.b.x, doors[d].line.b.y}, colour);
  }
  for (std::size_t k = 0; k < gateways.size(); ++k) {
    const DetectionOutcome o = match.outcomes[k];
    const Rgb colour = o == DetectionOutcome::kMatch ? Rgb{0, 0, 255}
                       : o == DetectionOutcome::kFalse ? Rgb{230, 0, 230}
                                                       : Rgb{0, 200, 220};
    canvas.line(gateways[k].left, gateways[k].right, colour);
  }
  writePng(path, canvas.image());
}

}  // namespace rgnav
