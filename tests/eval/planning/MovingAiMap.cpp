// MovingAiMap: the .map and .map.scen readers (see the header).
#include "tests/eval/planning/MovingAiMap.h"

#include <fstream>
#include <sstream>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

std::ifstream openFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw FileError("cannot open " + path);
  return in;
}

}  // namespace

OccupancyGrid loadMovingAiMap(const std::string& path) {
  std::ifstream in = openFile(path);
  std::string key, type;
  int height = 0, width = 0;
  if (!(in >> key >> type) || key != "type") throw FormatError(path, 1, "expected 'type octile'");
  if (!(in >> key >> height) || key != "height") throw FormatError(path, 2, "expected 'height H'");
  if (!(in >> key >> width) || key != "width") throw FormatError(path, 3, "expected 'width W'");
  if (!(in >> key) || key != "map") throw FormatError(path, 4, "expected 'map'");
  if (width <= 0 || height <= 0) throw FormatError(path, 2, "the map size must be positive");
  OccupancyGrid grid(width, height, 1.0, {}, Cell::Occupied);
  std::string line;
  std::getline(in, line);
  for (int y = 0; y < height; ++y) {
    if (!std::getline(in, line) || static_cast<int>(line.size()) < width)
      throw FormatError(path, static_cast<std::size_t>(5 + y), "expected a row of " + std::to_string(width) + " cells");
    for (int x = 0; x < width; ++x)
      if (line[static_cast<std::size_t>(x)] == '.' || line[static_cast<std::size_t>(x)] == 'G')
        grid.set({x, height - 1 - y}, Cell::Free);
  }
  return grid;
}

std::vector<MovingAiProblem> loadMovingAiScenario(const std::string& path, int height) {
  std::ifstream in = openFile(path);
  std::string line;
  if (!std::getline(in, line) || line.rfind("version", 0) != 0) throw FormatError(path, 1, "expected 'version 1'");
  std::vector<MovingAiProblem> problems;
  for (std::size_t number = 2; std::getline(in, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream fields(line);
    std::string map;
    int width = 0, mapHeight = 0, sx = 0, sy = 0, gx = 0, gy = 0;
    MovingAiProblem p;
    if (!(fields >> p.bucket >> map >> width >> mapHeight >> sx >> sy >> gx >> gy >> p.octileOptimum))
      throw FormatError(path, number, "expected 'bucket map width height sx sy gx gy length'");
    if (mapHeight != height) throw FormatError(path, number, "the problem's map height differs from the map's");
    p.start = {sx, height - 1 - sy};
    p.goal = {gx, height - 1 - gy};
    problems.push_back(p);
  }
  return problems;
}

}  // namespace rgnav
