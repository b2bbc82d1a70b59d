// VectorWorld: a building described by geometry instead of pixels, for the simulator's
// generated and hand-written worlds (issue 3; the simulated hallway environments of thesis
// 4.1.4). Walls with door openings, furniture as boxes and cylinders with heights, 3D
// rectangles on walls (posters, door frames: thesis 3, 4.2.2) kept for the camera simulator,
// and optional room polygons as ground truth. Rasterized by VectorWorldRaster.h; loaded from
// YAML by VectorWorldYaml.h, whose header documents the file format. Metres, radians, heights
// measured up from the floor.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

// A straight wall of the given thickness centred on from->to. It is solid from thickness/2
// before `from` to thickness/2 beyond `to` (square ends), so walls that meet at a corner close it.
struct Wall {
  std::string name;  // optional; doors and rectangles refer to walls by index once loaded
  WorldPoint from;
  WorldPoint to;
  double thickness = 0.1;
  double height = 2.5;
};

// An opening through a wall from the floor up to the door frame. A closed door blocks like the
// wall; its frame is still a rectangle for the camera.
struct Door {
  std::size_t wall = 0;     // index into VectorWorld::walls
  double offset = 0.0;      // along the wall from its `from` end to the opening's centre
  double width = 0.9;       // clear width of the opening
  double frameWidth = 1.01;  // outer width of the frame (thesis 3.3: 1.01 m x 2.10 m)
  double frameHeight = 2.10;
  bool open = true;
};

// A piece of furniture with a rectangular footprint; `length` runs along `yaw`.
struct Box {
  WorldPoint center;
  double length = 1.0;
  double width = 1.0;
  double yaw = 0.0;
  double height = 1.0;
  double elevation = 0.0;  // underside above the floor (a table top, a wall shelf)
};

struct Cylinder {
  WorldPoint center;
  double radius = 0.1;
  double height = 1.0;
  double elevation = 0.0;
};

// A flat rectangle in 3D, corners in order around it (world frame, z up).
struct Rectangle3D {
  std::string label;
  std::array<Eigen::Vector3d, 4> corners;
};

struct RoomPolygon {
  std::string name;
  std::vector<WorldPoint> polygon;  // simple polygon, at least 3 vertices
};

struct VectorWorld {
  double resolution = 0.05;  // cell size of the rasterized grid
  WorldPoint min;            // extent of the grid
  WorldPoint max;
  std::optional<OccupancyGrid> floorPlan;  // optional base layer; fixes resolution and extent
  std::vector<Wall> walls;
  std::vector<Door> doors;
  std::vector<Box> boxes;
  std::vector<Cylinder> cylinders;
  std::vector<Rectangle3D> rectangles;  // posters and the like; door frames come from doorFrames()
  std::vector<RoomPolygon> rooms;
};

// Wall geometry: unit direction from->to, length, and the point `along` metres from `from`
// and `left` metres to the left of the centre line.
Eigen::Vector2d wallDirection(const Wall& wall);
double wallLength(const Wall& wall);
Eigen::Vector2d pointOnWall(const Wall& wall, double along, double left);

enum class WallSide { Left, Right };  // seen walking from `from` to `to`

// A vertical rectangle on one face of a wall, centred `offset` along it, lower edge at
// `elevation`. Corners: lower start, lower end, upper end, upper start.
Rectangle3D rectangleOnWall(const Wall& wall, WallSide side, double offset, double width, double height,
                            double elevation, std::string label);

// The frame of every door as a rectangle on both faces of its wall, labelled "door_frame".
std::vector<Rectangle3D> doorFrames(const VectorWorld& world);

// The opening's centre line across the wall, along the wall's centre line.
std::array<WorldPoint, 2> doorOpening(const VectorWorld& world, const Door& door);

}  // namespace rgnav
