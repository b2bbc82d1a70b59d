// The RG Map as an SVG picture; see RgMapSvg.h.
#include "core/rgmap/export/RgMapSvg.h"

#include <cmath>
#include <initializer_list>
#include <string_view>

#include "core/common/AtomicFile.h"
#include "core/rgmap/export/ExportNumbers.h"
#include "core/rgmap/export/MapColours.h"
#include "core/rgmap/export/MapExtent.h"

namespace rgnav {
namespace {

constexpr double kLineWidthM = 0.04;
constexpr double kGatewayWidthM = 0.08;
constexpr double kGraphWidthM = 0.025;
constexpr double kCrossingRadiusM = 0.08;
constexpr double kRegionFontM = 0.4;
constexpr double kGatewayFontM = 0.2;

std::string num(double v) { return decimalText(v, kLengthDecimals); }
// A map-frame x or y as written (y negated: SVG's y runs down).
std::string x(double v) { return num(v); }
std::string y(double v) { return num(-v); }
std::string xy(const Eigen::Vector2d& p) { return x(p.x()) + " " + y(p.y()); }
// Appends the parts one by one (not "M" + text: GCC 12's -Wrestrict false alarm on such sums).
void append(std::string& out, std::initializer_list<std::string_view> parts) {
  for (const std::string_view part : parts) out += part;
}
std::string attr(const char* name, const std::string& value) { return std::string(" ") + name + "=\"" + value + "\""; }

std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// One rectangle per run of free cells in a row, in the region frame.
std::string freespacePath(const FreespaceBitmap& f) {
  std::string d;
  for (int row = 0; row < f.height; ++row) {
    for (int col = 0; col < f.width;) {
      if (!f.isFree(col, row)) {
        ++col;
        continue;
      }
      const int start = col;
      while (col < f.width && f.isFree(col, row)) ++col;
      const Eigen::Vector2d topLeft = f.originM + f.resolutionM * Eigen::Vector2d(start, row + 1);
      const double runM = (col - start) * f.resolutionM;
      append(d, {"M", xy(topLeft), "h", num(runM), "v", num(f.resolutionM), "h", num(-runM), "z"});
    }
  }
  return d;
}

std::string region(const RegionSnapshot& r) {
  const Pose2D& frame = r.region.frame;
  std::string out = "<g class=\"region\"" + attr("id", "region-" + std::to_string(r.region.id.value())) +
                    attr("transform", "translate(" + xy({frame.x, frame.y}) + ") rotate(" +
                                          decimalText(-frame.theta * 180.0 / M_PI, 2) + ")") +
                    ">\n";
  out += "<path class=\"freespace\"" + attr("fill", hexColour(regionColour(r.region.id))) +
         attr("d", freespacePath(r.description.freespace)) + "/>\n";
  std::string d;
  for (const LineSegment& s : r.lines) append(d, {"M", xy(s.start), "L", xy(s.end)});
  out += "<path class=\"lines\" fill=\"none\"" + attr("stroke", hexColour(kLineColour)) +
         attr("stroke-width", num(kLineWidthM)) + " stroke-linecap=\"round\"" + attr("d", d) + "/>\n";
  for (const Rectangle2D& o : r.description.objects) {
    std::string corners;
    for (const Eigen::Vector2d& p : rectangleOutline(o)) append(corners, {corners.empty() ? "" : " ", xy(p)});
    out += "<polygon class=\"object\" fill=\"none\"" + attr("stroke", hexColour(kObjectColour)) +
           attr("stroke-width", num(kLineWidthM)) + attr("points", corners) + "/>\n";
  }
  return out + "</g>\n";
}

std::string graph(const RgMapSnapshot& map) {
  std::string out = "<g class=\"graph\"" + attr("stroke", hexColour(kGraphColour)) +
                    attr("stroke-width", num(kGraphWidthM)) + ">\n";
  for (const RgEdge& e : map.graphEdges) {
    const Eigen::Vector2d& a = map.graphNodes[e.from].position;
    const Eigen::Vector2d& b = map.graphNodes[e.to].position;
    out += "<line" + attr("x1", x(a.x())) + attr("y1", y(a.y())) + attr("x2", x(b.x())) + attr("y2", y(b.y())) + "/>\n";
  }
  return out + "</g>\n";
}

std::string gateway(const GatewaySnapshot& s) {
  const Gateway& g = s.gateway;
  const std::vector<Eigen::Vector2d>& corners = s.inMap.gatewayPoints;
  std::string out = "<g class=\"gateway\"" + attr("id", "gateway-" + std::to_string(g.id.value())) + ">\n";
  const std::string style = attr("stroke", hexColour(gatewayColour(g.door(), g.neutralised))) +
                            attr("stroke-width", num(kGatewayWidthM)) +
                            (g.neutralised ? attr("stroke-dasharray", num(2 * kGatewayWidthM)) : "");
  if (g.door() && corners.size() >= 2) {
    out += "<line" + attr("x1", x(corners[0].x())) + attr("y1", y(corners[0].y())) + attr("x2", x(corners[1].x())) +
           attr("y2", y(corners[1].y())) + style + "/>\n";
  } else if (!corners.empty()) {
    std::string list;
    for (const Eigen::Vector2d& p : corners) append(list, {list.empty() ? "" : " ", x(p.x()), ",", y(p.y())});
    out += "<polygon fill=\"none\"" + attr("points", list) + style + "/>\n";
  }
  for (const Eigen::Vector2d& p : s.inMap.crossingPoints)
    out += "<circle class=\"crossing\"" + attr("cx", x(p.x())) + attr("cy", y(p.y())) +
           attr("r", num(kCrossingRadiusM)) + attr("fill", hexColour(kCrossingColour)) + "/>\n";
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& p : corners) centre += p / double(corners.size());
  std::string label = "G";
  label += std::to_string(g.id.value());
  if (!g.record.classes.empty()) append(label, {" ", g.record.label()});
  out += "<text class=\"gateway-label\"" + attr("x", x(centre.x())) + attr("y", y(centre.y() - 2 * kGatewayFontM)) +
         attr("font-size", num(kGatewayFontM)) + " text-anchor=\"middle\">" + escaped(label) + "</text>\n";
  return out + "</g>\n";
}

std::string regionLabel(const RegionSnapshot& r) {
  const Eigen::Vector2d at = r.labelPosition();
  const std::string text = std::to_string(r.region.id.value()) + (r.region.name.empty() ? "" : " " + r.region.name);
  return "<text class=\"region-label\"" + attr("x", x(at.x())) + attr("y", y(at.y())) +
         attr("font-size", num(kRegionFontM)) + " text-anchor=\"middle\" dominant-baseline=\"middle\">" +
         escaped(text) + "</text>\n";
}

// A round length of about a fifth of the picture's width.
double scaleBarLength(double widthM) {
  double best = 0.5;
  for (const double candidate : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0})
    if (candidate <= widthM / 5.0) best = candidate;
  return best;
}

std::string scaleBar(const Eigen::AlignedBox2d& extent) {
  const double length = scaleBarLength(extent.sizes().x());
  const Eigen::Vector2d from = extent.min() + Eigen::Vector2d::Constant(0.2);
  const Eigen::Vector2d to = from + Eigen::Vector2d(length, 0.0);
  return "<g class=\"scale-bar\">\n<line" + attr("x1", x(from.x())) + attr("y1", y(from.y())) + attr("x2", x(to.x())) +
         attr("y2", y(to.y())) + attr("stroke", hexColour(kLabelColour)) + attr("stroke-width", num(kGatewayWidthM)) +
         "/>\n<text" + attr("x", x(from.x())) + attr("y", y(from.y() + 0.1)) + attr("font-size", num(kGatewayFontM)) +
         ">" + decimalText(length, 1) + " m</text>\n</g>\n";
}

std::string overlay(const MapPolyline& line) {
  std::string points;
  for (const Eigen::Vector2d& p : line.points) append(points, {points.empty() ? "" : " ", x(p.x()), ",", y(p.y())});
  std::string out = "<g" + attr("class", escaped(line.cssClass)) + ">\n<polyline fill=\"none\"" + attr("points", points) +
                    attr("stroke", hexColour(line.colour)) + attr("stroke-width", num(line.widthM)) + "/>\n";
  if (line.markerRadiusM > 0.0)
    for (const Eigen::Vector2d& p : line.points)
      out += "<circle" + attr("cx", x(p.x())) + attr("cy", y(p.y())) + attr("r", num(line.markerRadiusM)) +
             attr("fill", hexColour(line.colour)) + "/>\n";
  return out + "</g>\n";
}

}  // namespace

std::string exportRgMapSvg(const RgMapSnapshot& map, const std::vector<MapPolyline>& overlays) {
  const Eigen::AlignedBox2d extent = pictureExtent(map);
  const Eigen::Vector2d size = extent.sizes();
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"" +
                    attr("width", decimalText(std::ceil(size.x() * kSvgPixelsPerMetre), 0)) +
                    attr("height", decimalText(std::ceil(size.y() * kSvgPixelsPerMetre), 0)) +
                    attr("viewBox", x(extent.min().x()) + " " + y(extent.max().y()) + " " + num(size.x()) + " " +
                                        num(size.y())) +
                    " font-family=\"sans-serif\">\n";
  out += "<title>RG Map: " + std::to_string(map.regions.size()) + " regions, " + std::to_string(map.gateways.size()) +
         " gateways</title>\n";
  out += "<rect class=\"background\"" + attr("x", x(extent.min().x())) + attr("y", y(extent.max().y())) +
         attr("width", num(size.x())) + attr("height", num(size.y())) + attr("fill", hexColour(kBackgroundColour)) +
         "/>\n";
  for (const RegionSnapshot& r : map.regions) out += region(r);
  out += graph(map);
  for (const GatewaySnapshot& g : map.gateways) out += gateway(g);
  for (const RegionSnapshot& r : map.regions) out += regionLabel(r);
  for (const MapPolyline& line : overlays) out += overlay(line);
  return out + scaleBar(extent) + "</svg>\n";
}

void writeRgMapSvg(const std::string& path, const RgMapSnapshot& map, const std::vector<MapPolyline>& overlays) {
  writeFileAtomically(path, exportRgMapSvg(map, overlays));
}

}  // namespace rgnav
