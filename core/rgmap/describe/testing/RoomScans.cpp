// Rooms and their scans for tests; see RoomScans.h.
#include "core/rgmap/describe/testing/RoomScans.h"

namespace rgnav::testing {

std::vector<Wall> roomWalls(const Eigen::AlignedBox2d& room, std::optional<Door> door) {
  const Eigen::Vector2d sw = room.min(), ne = room.max(), se(ne.x(), sw.y()), nw(sw.x(), ne.y());
  std::vector<Wall> walls{{sw, se}, {ne, nw}, {nw, sw}};
  if (door) {
    walls.push_back({se, {ne.x(), door->lowY}});
    walls.push_back({{ne.x(), door->highY}, ne});
  } else {
    walls.push_back({se, ne});
  }
  return walls;
}

std::vector<Pose2D> roomPoses(const Eigen::AlignedBox2d& room, double marginM, int nx, int ny) {
  const Eigen::Vector2d lo = room.min() + Eigen::Vector2d::Constant(marginM);
  const Eigen::Vector2d step = (room.sizes() - Eigen::Vector2d::Constant(2 * marginM)).cwiseQuotient(
      Eigen::Vector2d(std::max(1, nx - 1), std::max(1, ny - 1)));
  std::vector<Pose2D> poses;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      poses.push_back({lo.x() + i * step.x(), lo.y() + j * step.y(), normalizeAngle(1.3 * double(poses.size()))});
  return poses;
}

std::vector<LaserScan> scansFrom(const std::vector<Wall>& walls, const std::vector<Pose2D>& poses, double noiseSigmaM) {
  std::vector<LaserScan> scans;
  for (const Pose2D& pose : poses) {
    ScanSpec spec;
    spec.noiseSigmaM = noiseSigmaM;
    spec.seed = unsigned(scans.size() + 1);
    scans.push_back(syntheticScan(walls, pose, spec));
  }
  return scans;
}

}  // namespace rgnav::testing
