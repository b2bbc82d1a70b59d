// The RG Map as a PNG picture; see RgMapPng.h.
#include "core/rgmap/export/RgMapPng.h"


#include "core/rgmap/describe/FreespaceRaster.h"
#include "core/rgmap/export/MapCanvas.h"
#include "core/rgmap/export/MapColours.h"
#include "core/rgmap/export/MapExtent.h"
#include "core/sim/world/PngIo.h"

namespace rgnav {
namespace {

constexpr int kDoorWidthPixels = 3;
constexpr int kHallwayAreaWidthPixels = 2;
constexpr int kCrossingRadiusPixels = 2;
constexpr int kDigitScale = 2;
constexpr int kLabelLiftPixels = 3;

void paintFreespace(MapCanvas& canvas, const RegionSnapshot& r) {
  const RgbImage& image = canvas.image();
  const RasterFrame frame{canvas.resolutionM(), canvas.originM(), image.width(), image.height()};
  const std::vector<std::uint8_t> raster = rasteriseFreespace(r.description.freespace, r.region.frame, frame);
  const Rgb colour = regionColour(r.region.id);
  for (int row = 0; row < frame.height; ++row)
    for (int col = 0; col < frame.width; ++col)
      if (raster[std::size_t(row) * std::size_t(frame.width) + std::size_t(col)])
        canvas.setPixel(col, frame.height - 1 - row, colour);
}

void paintGateway(MapCanvas& canvas, const GatewaySnapshot& s) {
  const Gateway& g = s.gateway;
  const std::vector<Eigen::Vector2d>& corners = s.inMap.gatewayPoints;
  const Rgb colour = gatewayColour(g.door(), g.neutralised);
  if (g.door() && corners.size() >= 2) {
    canvas.line(corners[0], corners[1], colour, kDoorWidthPixels);
  } else {
    for (std::size_t k = 0; k < corners.size(); ++k)
      canvas.line(corners[k], corners[(k + 1) % corners.size()], colour, kHallwayAreaWidthPixels);
  }
  for (const Eigen::Vector2d& p : s.inMap.crossingPoints) canvas.disc(p, kCrossingRadiusPixels, kCrossingColour);
}

}  // namespace

RgbImage renderRgMap(const RgMapSnapshot& map, double resolutionM) {
  MapCanvas canvas(pictureExtent(map), resolutionM, kBackgroundColour);
  for (const RegionSnapshot& r : map.regions) paintFreespace(canvas, r);
  for (const RgEdge& e : map.graphEdges)
    canvas.line(map.graphNodes[e.from].position, map.graphNodes[e.to].position, kGraphColour, 1);
  for (const RegionSnapshot& r : map.regions)
    for (const LineSegment& s : r.lines) canvas.line(r.toMap(s.start), r.toMap(s.end), kLineColour, 1);
  for (const GatewaySnapshot& g : map.gateways) paintGateway(canvas, g);
  for (const RegionSnapshot& r : map.regions)
    canvas.number(r.labelPosition(), r.region.id, kDigitScale, kLabelLiftPixels, kLabelColour);
  return canvas.image();
}

void exportRgMapPng(const std::string& path, const RgMapSnapshot& map, double resolutionM) {
  writePng(path, renderRgMap(map, resolutionM));
}

}  // namespace rgnav
