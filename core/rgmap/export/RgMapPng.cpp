// The RG Map as a PNG picture; see RgMapPng.h.
#include "core/rgmap/export/RgMapPng.h"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>

#include "core/raster/ImageFile.h"
#include "core/rgmap/describe/FreespaceRaster.h"
#include "core/rgmap/export/MapCanvas.h"
#include "core/rgmap/export/MapColours.h"
#include "core/rgmap/export/MapExtent.h"

namespace rgnav {
namespace {

constexpr int kDoorWidthPixels = 3;
constexpr int kHallwayAreaWidthPixels = 2;
constexpr int kCrossingRadiusPixels = 2;
constexpr int kDigitScale = 2;
constexpr int kLabelLiftPixels = 3;

void paintFreespace(MapCanvas& canvas, const RegionSnapshot& r) {
  const cv::Mat& image = canvas.image();
  const RasterFrame frame{canvas.resolutionM(), canvas.originM(), image.cols, image.rows};
  std::vector<std::uint8_t> raster = rasteriseFreespace(r.description.freespace, r.region.frame, frame);
  // The raster's row 0 is the bottom, the canvas's the top.
  cv::Mat mask;
  cv::flip(cv::Mat(frame.height, frame.width, CV_8UC1, raster.data()), mask, 0);
  canvas.fill(mask, regionColour(r.region.id));
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

void paintOverlay(MapCanvas& canvas, const MapPolyline& line) {
  const int width = std::max(1, static_cast<int>(std::lround(line.widthM / canvas.resolutionM())));
  for (std::size_t k = 1; k < line.points.size(); ++k) canvas.line(line.points[k - 1], line.points[k], line.colour, width);
  const int radius = static_cast<int>(std::lround(line.markerRadiusM / canvas.resolutionM()));
  if (line.markerRadiusM > 0.0)
    for (const Eigen::Vector2d& p : line.points) canvas.disc(p, std::max(1, radius), line.colour);
}

}  // namespace

cv::Mat renderRgMap(const RgMapSnapshot& map, double resolutionM, const std::vector<MapPolyline>& overlays) {
  MapCanvas canvas(pictureExtent(map), resolutionM, kBackgroundColour);
  for (const RegionSnapshot& r : map.regions) paintFreespace(canvas, r);
  for (const RgEdge& e : map.graphEdges)
    canvas.line(map.graphNodes[e.from].position, map.graphNodes[e.to].position, kGraphColour, 1);
  for (const RegionSnapshot& r : map.regions)
    for (const LineSegment& s : r.lines) canvas.line(r.toMap(s.start), r.toMap(s.end), kLineColour, 1);
  for (const GatewaySnapshot& g : map.gateways) paintGateway(canvas, g);
  for (const RegionSnapshot& r : map.regions)
    canvas.number(r.labelPosition(), r.region.id.value(), kDigitScale, kLabelLiftPixels, kLabelColour);
  for (const MapPolyline& line : overlays) paintOverlay(canvas, line);
  return canvas.image();
}

void exportRgMapPng(const std::string& path, const RgMapSnapshot& map, double resolutionM,
                    const std::vector<MapPolyline>& overlays) {
  writeImage(path, renderRgMap(map, resolutionM, overlays));
}

}  // namespace rgnav
