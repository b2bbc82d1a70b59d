// An RG map exported to JSON (RgMapJson.h) and read back into a PlanningMap equals what the kernel
// serves of it (RgMapViews.h) up to the export's rounding: every region with its frame, lines,
// freespace bits and named objects, the map's gateways (also those no region has taken in), the
// graph's nodes and edges with their costs, and the revision; a gateway hypothesis in the file is
// read as a gateway without sides. Files of another format or version, with a freespace whose size and
// bits disagree, or with an edge naming an unknown node, are FormatErrors naming the source.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/common/Errors.h"
#include "core/nav/planning/PlanningMapJson.h"
#include "core/rgmap/export/RgMapJson.h"
#include "core/rgmap/export/testing/ExportedFloor.h"
#include "core/rgmap/kernel/RgMapViews.h"
#include "core/rgmap/kernel/testing/SyntheticTour.h"

using namespace rgnav;

namespace {

constexpr double kMm = 0.0005 + 1e-9;  // the export rounds positions to 1 mm
constexpr double kAngle = 0.00005 + 1e-9;

bool near(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return (a - b).cwiseAbs().maxCoeff() <= kMm; }

// The message of the FormatError reading `text` ends in; "(read)" if it was read.
std::string formatErrorOf(const std::string& text) {
  try {
    planningMapFromJson(text, "map");
  } catch (const FormatError& e) {
    return e.what();
  }
  return "(read)";
}

}  // namespace

class PlanningMapJsonTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(PlanningMapJsonTest);
  CPPUNIT_TEST(exportedMapReadsBack);
  CPPUNIT_TEST(gatewayHypothesesAreRead);
  CPPUNIT_TEST(otherFilesAreRefused);
  CPPUNIT_TEST_SUITE_END();

 public:
  void exportedMapReadsBack() {
    RgMappingKernel kernel = testing::twoRoomMap();
    const RegionId room1 = kernel.state().regions.begin()->first;
    kernel.nameRegion(room1, "hall");
    const PlanningMap map = planningMapFromJson(exportRgMapJson(snapshotOf(kernel)), "two-room");
    CPPUNIT_ASSERT_EQUAL(kernel.state().regions.size(), map.regions.size());
    for (const RegionView& read : map.regions) {
      const RegionView served = regionView(kernel, read.summary.id);
      CPPUNIT_ASSERT_EQUAL(served.summary.name, read.summary.name);
      CPPUNIT_ASSERT(served.summary.gateways == read.summary.gateways);
      CPPUNIT_ASSERT_EQUAL(served.summary.scans, read.summary.scans);
      CPPUNIT_ASSERT(near({served.summary.frame.x, served.summary.frame.y}, {read.summary.frame.x, read.summary.frame.y}));
      CPPUNIT_ASSERT_DOUBLES_EQUAL(served.summary.frame.theta, read.summary.frame.theta, kAngle);
      CPPUNIT_ASSERT_EQUAL(served.lines.size(), read.lines.size());
      CPPUNIT_ASSERT(!read.lines.empty());
      for (std::size_t i = 0; i < read.lines.size(); ++i)
        CPPUNIT_ASSERT(near(served.lines[i].a, read.lines[i].a) && near(served.lines[i].b, read.lines[i].b));
      CPPUNIT_ASSERT(served.freespace.bytes == read.freespace.bytes);
      CPPUNIT_ASSERT_EQUAL(served.freespace.width, read.freespace.width);
      CPPUNIT_ASSERT_EQUAL(served.freespace.height, read.freespace.height);
      CPPUNIT_ASSERT(near(served.freespace.originM, read.freespace.originM));
      CPPUNIT_ASSERT(near(served.centroid, read.centroid));
      CPPUNIT_ASSERT_EQUAL(served.objects.size(), read.objects.size());
      for (std::size_t i = 0; i < read.objects.size(); ++i) CPPUNIT_ASSERT_EQUAL(served.objects[i].name, read.objects[i].name);
    }
    CPPUNIT_ASSERT_EQUAL(std::string("hall"), map.regions.front().summary.name);
    // Every gateway the module plans with, those no region has taken in yet too.
    const std::vector<GatewayView> served = gatewayViews(kernel);
    CPPUNIT_ASSERT_EQUAL(served.size(), map.gateways.size());
    CPPUNIT_ASSERT(!served.empty());
    for (const GatewayView& s : served) {
      const auto read = std::find_if(map.gateways.begin(), map.gateways.end(), [&](const GatewayView& g) { return g.id == s.id; });
      CPPUNIT_ASSERT(read != map.gateways.end());
      CPPUNIT_ASSERT_EQUAL(s.door, read->door);
      CPPUNIT_ASSERT(s.sideA == read->sideA && s.sideB == read->sideB);
      CPPUNIT_ASSERT_EQUAL(s.crossingPoints.size(), read->crossingPoints.size());
      for (std::size_t k = 0; k < s.crossingPoints.size(); ++k) CPPUNIT_ASSERT(near(s.crossingPoints[k], read->crossingPoints[k]));
    }
    const GraphView graph = graphView(kernel.graph());
    CPPUNIT_ASSERT_EQUAL(graph.nodes.size(), map.graph.nodes.size());
    CPPUNIT_ASSERT_EQUAL(graph.edges.size(), map.graph.edges.size());
    CPPUNIT_ASSERT(!graph.edges.empty());
    for (std::size_t i = 0; i < graph.nodes.size(); ++i) {
      CPPUNIT_ASSERT(graph.nodes[i].gateway == map.graph.nodes[i].gateway);
      CPPUNIT_ASSERT_EQUAL(graph.nodes[i].side, map.graph.nodes[i].side);
      CPPUNIT_ASSERT(graph.nodes[i].region == map.graph.nodes[i].region);
      CPPUNIT_ASSERT(near(graph.nodes[i].position, map.graph.nodes[i].position));
    }
    for (std::size_t i = 0; i < graph.edges.size(); ++i) {
      const GraphEdgeView &a = graph.edges[i], &b = map.graph.edges[i];
      CPPUNIT_ASSERT(a.from == b.from && a.to == b.to && a.gateway == b.gateway && a.region == b.region);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(a.costM, b.costM, kMm);
    }
    CPPUNIT_ASSERT_EQUAL(kernel.state().events.back().id, map.revision);
  }

  // A detected gateway no region has taken in is exported apart ("gatewayHypotheses"); the
  // PathPlanning module plans with it, so the map read back has it too, without sides.
  void gatewayHypothesesAreRead() {
    nlohmann::json j = nlohmann::json::parse(exportRgMapJson(snapshotOf(testing::twoRoomMap())));
    nlohmann::json hypothesis = j["gateways"][0];
    hypothesis["id"] = 999;
    hypothesis["sides"][0]["region"] = nullptr;
    hypothesis["sides"][1]["region"] = nullptr;
    j["gatewayHypotheses"].push_back(hypothesis);
    const PlanningMap map = planningMapFromJson(j.dump(), "with-hypothesis");
    CPPUNIT_ASSERT_EQUAL(j["gateways"].size() + 1, map.gateways.size());
    const GatewayView& read = map.gateways.back();
    CPPUNIT_ASSERT(read.id == GatewayId{999});
    CPPUNIT_ASSERT(read.sideA.isNone() && read.sideB.isNone());
    CPPUNIT_ASSERT_EQUAL(hypothesis["crossingPoints"].size(), read.crossingPoints.size());
  }

  void otherFilesAreRefused() {
    const std::string text = exportRgMapJson(snapshotOf(testing::twoRoomMap()));
    nlohmann::json j = nlohmann::json::parse(text);
    j["version"] = 1;
    CPPUNIT_ASSERT_THROW(planningMapFromJson(j.dump(), "old"), FormatError);
    j = nlohmann::json::parse(text);
    j["graph"]["edges"][0]["from"] = "G99A";
    try {
      planningMapFromJson(j.dump(), "broken.rgmap.json");
      CPPUNIT_FAIL("an edge naming an unknown node was accepted");
    } catch (const FormatError& e) {
      CPPUNIT_ASSERT(std::string(e.what()).find("broken.rgmap.json") == 0);
      CPPUNIT_ASSERT(std::string(e.what()).find("G99A") != std::string::npos);
    }
    CPPUNIT_ASSERT_THROW(planningMapFromJson("{", "cut"), FormatError);
    j = nlohmann::json::parse(text);
    j["regions"][0]["freespace"]["width"] = -1;
    j["regions"][0]["freespace"]["height"] = 0;
    j["regions"][0]["freespace"]["bits"] = "";
    const std::string negative = formatErrorOf(j.dump());
    CPPUNIT_ASSERT_MESSAGE(negative, negative.find("-1 x 0 cells") != std::string::npos);
    j = nlohmann::json::parse(text);
    j["regions"][0]["freespace"]["height"] = j["regions"][0]["freespace"]["height"].get<int>() + 100;
    const std::string shortBits = formatErrorOf(j.dump());
    CPPUNIT_ASSERT_MESSAGE(shortBits, shortBits.find("freespace bytes for") != std::string::npos);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(PlanningMapJsonTest);
