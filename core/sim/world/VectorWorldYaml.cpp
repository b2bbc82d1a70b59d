// loadVectorWorld: strict YAML parsing of vector worlds, one reader per element kind.
#include "core/sim/world/VectorWorldYaml.h"

#include <cmath>
#include <map>

#include "core/sim/world/FloorPlan.h"
#include "core/sim/world/WorldYaml.h"

namespace rgnav {
namespace {

constexpr double kDefaultWallHeight = 2.5;
constexpr double kDefaultFrameHeight = 2.10;

template <typename Read>
auto readList(const ConfigNode& root, const char* key, Read read) {
  std::vector<decltype(read(root))> out;
  if (!root.has(key)) return out;
  for (const ConfigNode& item : root[key].items()) out.push_back(read(item));
  return out;
}

double optionalNumber(const ConfigNode& node, const char* key, double fallback) {
  return node.has(key) ? node[key].asDouble() : fallback;
}

void readExtent(const ConfigNode& root, const std::string& yamlPath, VectorWorld& world) {
  const int given = int(root.has("size")) + int(root.has("bounds")) + int(root.has("floor_plan"));
  if (given != 1) root.fail("exactly one of size, bounds and floor_plan must give the extent");
  if (root.has("size")) {
    const ConfigNode size = root["size"];
    const WorldPoint extent = readPoint(size);
    if (!(extent.x > 0.0 && extent.y > 0.0)) size.fail("must be positive");
    world.max = extent;
  } else if (root.has("bounds")) {
    const ConfigNode bounds = root["bounds"];
    bounds.expectKeys({"min", "max"});
    world.min = readPoint(bounds["min"]);
    world.max = readPoint(bounds["max"]);
    if (!(world.max.x > world.min.x && world.max.y > world.min.y)) bounds["max"].fail("must exceed min");
  } else {
    const ConfigNode plan = root["floor_plan"];
    plan.expectKeys({"image", "origin"});
    world.min = plan.has("origin") ? readPoint(plan["origin"]) : WorldPoint{};
    const cv::Mat image = readReferencedImage(yamlPath, plan["image"]);
    world.floorPlan = floorPlanFromImage(image, world.resolution, world.min);
    world.max = {world.min.x + image.cols * world.resolution, world.min.y + image.rows * world.resolution};
  }
}

Wall readWall(const ConfigNode& node) {
  node.expectKeys({"name", "from", "to", "thickness", "height"});
  Wall wall;
  if (node.has("name")) wall.name = node["name"].asString();
  wall.from = readPoint(node["from"]);
  wall.to = readPoint(node["to"]);
  if (!(wallLength(wall) > 0.0)) node["to"].fail("must differ from `from`");
  wall.thickness = readPositive(node["thickness"]);
  wall.height = node.has("height") ? readPositive(node["height"]) : kDefaultWallHeight;
  return wall;
}

std::map<std::string, std::size_t> wallIndex(const std::vector<Wall>& walls, const ConfigNode& root) {
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < walls.size(); ++i) {
    if (!walls[i].name.empty() && !index.emplace(walls[i].name, i).second) {
      root["walls"].items()[i]["name"].fail("duplicate wall name \"" + walls[i].name + "\"");
    }
  }
  return index;
}

std::size_t readWallReference(const ConfigNode& node, const std::map<std::string, std::size_t>& walls) {
  const std::string name = node.asString();
  const auto found = walls.find(name);
  if (found == walls.end()) node.fail("no wall named \"" + name + "\"");
  return found->second;
}

// Distance along the wall of a point given as `offset` or `center`.
double readOffset(const ConfigNode& node, const Wall& wall) {
  if (node.has("offset") == node.has("center")) node.fail("exactly one of offset and center is required");
  if (node.has("offset")) return node["offset"].asDouble();
  const WorldPoint c = readPoint(node["center"]);
  const Eigen::Vector2d fromStart(c.x - wall.from.x, c.y - wall.from.y);
  const Eigen::Vector2d u = wallDirection(wall);
  const double across = u.x() * fromStart.y() - u.y() * fromStart.x();
  if (std::abs(across) > wall.thickness) node["center"].fail("is not on the wall");
  return u.dot(fromStart);
}

Door readDoor(const ConfigNode& node, const std::vector<Wall>& walls,
              const std::map<std::string, std::size_t>& names) {
  node.expectKeys({"wall", "offset", "center", "width", "frame_width", "frame_height", "open"});
  Door door;
  door.wall = readWallReference(node["wall"], names);
  const Wall& wall = walls[door.wall];
  door.offset = readOffset(node, wall);
  door.width = readPositive(node["width"]);
  if (door.offset - door.width / 2.0 < 0.0 || door.offset + door.width / 2.0 > wallLength(wall)) {
    node["width"].fail("the opening does not fit into the wall");
  }
  door.frameWidth = node.has("frame_width") ? readPositive(node["frame_width"]) : door.width;
  if (door.frameWidth < door.width) node["frame_width"].fail("must be at least the width");
  door.frameHeight = node.has("frame_height") ? readPositive(node["frame_height"]) : kDefaultFrameHeight;
  door.open = !node.has("open") || node["open"].asBool();
  return door;
}

Box readBox(const ConfigNode& node) {
  node.expectKeys({"center", "size", "yaw", "height", "elevation"});
  Box box;
  box.center = readPoint(node["center"]);
  const WorldPoint size = readPoint(node["size"]);
  if (!(size.x > 0.0 && size.y > 0.0)) node["size"].fail("must be positive");
  box.length = size.x;
  box.width = size.y;
  box.yaw = optionalNumber(node, "yaw", 0.0);
  box.height = readPositive(node["height"]);
  box.elevation = node.has("elevation") ? readNonNegative(node["elevation"]) : 0.0;
  return box;
}

Cylinder readCylinder(const ConfigNode& node) {
  node.expectKeys({"center", "radius", "height", "elevation"});
  Cylinder cylinder;
  cylinder.center = readPoint(node["center"]);
  cylinder.radius = readPositive(node["radius"]);
  cylinder.height = readPositive(node["height"]);
  cylinder.elevation = node.has("elevation") ? readNonNegative(node["elevation"]) : 0.0;
  return cylinder;
}

WallSide readSide(const ConfigNode& node) {
  const std::string side = node.asString();
  if (side == "left") return WallSide::Left;
  if (side == "right") return WallSide::Right;
  node.fail("must be left or right");
}

Rectangle3D readRectangle(const ConfigNode& node, const std::vector<Wall>& walls,
                          const std::map<std::string, std::size_t>& names) {
  const std::string label = node.has("label") ? node["label"].asString() : std::string();
  if (node.has("corners")) {
    node.expectKeys({"label", "corners"});
    const std::vector<ConfigNode> corners = node["corners"].items();
    if (corners.size() != 4) node["corners"].fail("expected 4 corners");
    Rectangle3D rectangle{label, {}};
    for (std::size_t i = 0; i < 4; ++i) rectangle.corners[i] = readPoint3(corners[i]);
    return rectangle;
  }
  node.expectKeys({"label", "wall", "side", "offset", "width", "height", "elevation"});
  const Wall& wall = walls[readWallReference(node["wall"], names)];
  return rectangleOnWall(wall, readSide(node["side"]), node["offset"].asDouble(), readPositive(node["width"]),
                         readPositive(node["height"]), optionalNumber(node, "elevation", 0.0), label);
}

RoomPolygon readRoom(const ConfigNode& node) {
  node.expectKeys({"name", "polygon"});
  RoomPolygon room;
  if (node.has("name")) room.name = node["name"].asString();
  for (const ConfigNode& vertex : node["polygon"].items()) room.polygon.push_back(readPoint(vertex));
  if (room.polygon.size() < 3) node["polygon"].fail("needs at least 3 vertices");
  return room;
}

}  // namespace

VectorWorld loadVectorWorld(const std::string& yamlPath) {
  return parseYamlFile(yamlPath, [&](const ConfigNode& root) {
    root.expectKeys({"resolution", "size", "bounds", "floor_plan", "walls", "doors", "boxes", "cylinders",
                     "rectangles3d", "rooms"});
    VectorWorld world;
    if (root.has("resolution")) world.resolution = readPositive(root["resolution"]);
    world.walls = readList(root, "walls", readWall);
    const std::map<std::string, std::size_t> names = wallIndex(world.walls, root);
    world.doors = readList(root, "doors", [&](const ConfigNode& n) { return readDoor(n, world.walls, names); });
    world.boxes = readList(root, "boxes", readBox);
    world.cylinders = readList(root, "cylinders", readCylinder);
    world.rectangles =
        readList(root, "rectangles3d", [&](const ConfigNode& n) { return readRectangle(n, world.walls, names); });
    world.rooms = readList(root, "rooms", readRoom);
    readExtent(root, yamlPath, world);
    return world;
  });
}

}  // namespace rgnav
