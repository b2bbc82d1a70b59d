// Wall geometry of vector worlds: points on walls, rectangles on wall faces, door frames.
#include "core/sim/world/VectorWorld.h"

#include <cmath>

namespace rgnav {

Eigen::Vector2d wallDirection(const Wall& wall) {
  return Eigen::Vector2d(wall.to.x - wall.from.x, wall.to.y - wall.from.y).normalized();
}

double wallLength(const Wall& wall) { return std::hypot(wall.to.x - wall.from.x, wall.to.y - wall.from.y); }

Eigen::Vector2d pointOnWall(const Wall& wall, double along, double left) {
  const Eigen::Vector2d u = wallDirection(wall);
  return Eigen::Vector2d(wall.from.x, wall.from.y) + along * u + left * Eigen::Vector2d(-u.y(), u.x());
}

Rectangle3D rectangleOnWall(const Wall& wall, WallSide side, double offset, double width, double height,
                            double elevation, std::string label) {
  const double face = (side == WallSide::Left ? 0.5 : -0.5) * wall.thickness;
  const Eigen::Vector2d start = pointOnWall(wall, offset - width / 2.0, face);
  const Eigen::Vector2d end = pointOnWall(wall, offset + width / 2.0, face);
  const double top = elevation + height;
  return {std::move(label),
          {Eigen::Vector3d(start.x(), start.y(), elevation), Eigen::Vector3d(end.x(), end.y(), elevation),
           Eigen::Vector3d(end.x(), end.y(), top), Eigen::Vector3d(start.x(), start.y(), top)}};
}

std::vector<Rectangle3D> doorFrames(const VectorWorld& world) {
  std::vector<Rectangle3D> frames;
  for (const Door& door : world.doors) {
    const Wall& wall = world.walls.at(door.wall);
    for (const WallSide side : {WallSide::Left, WallSide::Right}) {
      frames.push_back(rectangleOnWall(wall, side, door.offset, door.frameWidth, door.frameHeight, 0.0, "door_frame"));
    }
  }
  return frames;
}

std::array<WorldPoint, 2> doorOpening(const VectorWorld& world, const Door& door) {
  const Wall& wall = world.walls.at(door.wall);
  const Eigen::Vector2d a = pointOnWall(wall, door.offset - door.width / 2.0, 0.0);
  const Eigen::Vector2d b = pointOnWall(wall, door.offset + door.width / 2.0, 0.0);
  return {WorldPoint{a.x(), a.y()}, WorldPoint{b.x(), b.y()}};
}

}  // namespace rgnav
