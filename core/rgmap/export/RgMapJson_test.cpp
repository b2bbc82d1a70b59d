// Tests the RG Map's JSON export on the map of the two-room tour: it parses back with the right
// format, counts, IDs and fields, gateways in the map frame with their sides, the RG Graph, the
// freespace bits decoding to the region's bitmap, rounded values, the same bytes for the same
// map and an atomically written file; a crossing seen but never traversed is exported as a
// gateway hypothesis, apart from the map's gateways, each of which has a region on a side.
#include "core/rgmap/export/RgMapJson.h"

#include <cppunit/extensions/HelperMacros.h>

#include <nlohmann/json.hpp>
#include <regex>

#include "core/common/AtomicFile.h"
#include "core/common/Errors.h"
#include "core/common/JsonForms.h"
#include "core/logs/LogTestFiles.h"
#include "core/rgmap/export/Base64.h"
#include "core/rgmap/export/testing/ExportedFloor.h"
#include "core/rgmap/kernel/testing/SyntheticTour.h"

using namespace rgnav;
using nlohmann::json;

class RgMapJsonTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RgMapJsonTest);
  CPPUNIT_TEST(parsesWithFormatAndCounts);
  CPPUNIT_TEST(regionsHaveEveryField);
  CPPUNIT_TEST(gatewaysLieInTheMapFrameWithTheirSides);
  CPPUNIT_TEST(graphMatchesTheKernel);
  CPPUNIT_TEST(freespaceBitsDecodeToTheBitmap);
  CPPUNIT_TEST(sameMapGivesSameBytes);
  CPPUNIT_TEST(valuesAreRounded);
  CPPUNIT_TEST(fileIsWritten);
  CPPUNIT_TEST(unreachedAreaIsAHypothesis);
  CPPUNIT_TEST_SUITE_END();

 public:
  void setUp() override {
    kernel_ = std::make_unique<RgMappingKernel>(rgnav::testing::twoRoomMap());
    snapshot_ = snapshotOf(*kernel_);
    text_ = exportRgMapJson(snapshot_);
    doc_ = json::parse(text_);
  }

  void parsesWithFormatAndCounts() {
    CPPUNIT_ASSERT_EQUAL(std::string("rgnav-rgmap"), doc_["format"].get<std::string>());
    CPPUNIT_ASSERT_EQUAL(2, doc_["version"].get<int>());
    const json& s = doc_["summary"];
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), s["regions"].get<std::size_t>());
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), s["gateways"].get<std::size_t>());
    CPPUNIT_ASSERT_EQUAL(std::size_t(0), s["neutralisedGateways"].get<std::size_t>());
    CPPUNIT_ASSERT_EQUAL(kernel_->state().scans.size(), s["scans"].get<std::size_t>());
    CPPUNIT_ASSERT_EQUAL(kernel_->state().lastScanId, s["lastScanId"].get<DataId>());
    CPPUNIT_ASSERT_EQUAL(kernel_->state().events.back().id, s["lastEventId"].get<RgMapEventId>());
    CPPUNIT_ASSERT_EQUAL(kernel_->currentRegionId(), s["currentRegion"].get<RegionId>());
    // Thesis 5.2: the RG Map is far smaller than a grid of the same extent.
    CPPUNIT_ASSERT(s["rgMapBytes"].get<std::size_t>() > 0);
    CPPUNIT_ASSERT(s["rgMapBytes"].get<std::size_t>() * 5 < s["occupancyGridBytes"].get<std::size_t>());
    CPPUNIT_ASSERT_EQUAL(0.05, s["occupancyGridResolution"].get<double>());
    std::vector<RegionId> ids;
    for (const json& r : doc_["regions"]) ids.push_back(r["id"].get<RegionId>());
    CPPUNIT_ASSERT((ids == std::vector<RegionId>{RegionId{1}, RegionId{2}, RegionId{3}}));
  }

  void regionsHaveEveryField() {
    for (const json& r : doc_["regions"]) {
      for (const char* key : {"id", "name", "frame", "finalised", "scanCount", "gateways", "lines", "boundingBox",
                              "minimumAreaBox", "freespace", "area", "centroid", "centroidInBox", "mainAxes",
                              "mainDirections", "accuracy", "completeness"})
        CPPUNIT_ASSERT_MESSAGE(key, r.contains(key));
      const Region& region = kernel_->state().regions.at(r["id"].get<RegionId>());
      CPPUNIT_ASSERT_EQUAL(region.scans.size(), r["scanCount"].get<std::size_t>());
      CPPUNIT_ASSERT_EQUAL(kernel_->lineMap(region.id).lineCount(), r["lines"].size());
      CPPUNIT_ASSERT_EQUAL(std::size_t(4), r["lines"][0].size());
      // Written with 3 decimals (halves away from zero): within half a step, up to the binary error.
      CPPUNIT_ASSERT_DOUBLES_EQUAL(region.frame.x, r["frame"]["x"].get<double>(), 5e-4 + 1e-9);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(kernel_->description(region.id).moments.areaM2, r["area"].get<double>(),
                                   5e-4 + 1e-9);
      CPPUNIT_ASSERT(r["area"].get<double>() > 5.0);
      CPPUNIT_ASSERT(!r["boundingBox"].is_null() && !r["minimumAreaBox"].is_null());
      CPPUNIT_ASSERT(!r["mainDirections"].empty());
      CPPUNIT_ASSERT(r["completeness"]["value"].get<double>() > 0.0);
      CPPUNIT_ASSERT(r["accuracy"]["points"].get<std::size_t>() > 0);
      CPPUNIT_ASSERT(std::vector<GatewayId>(region.gateways.begin(), region.gateways.end()) ==
                     r["gateways"].get<std::vector<GatewayId>>());
    }
  }

  void gatewaysLieInTheMapFrameWithTheirSides() {
    const json& gateways = doc_["gateways"];
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), gateways.size());
    const double doorX[] = {4.0, 9.0};
    const DetectorGatewayId detector[] = {DetectorGatewayId{11}, DetectorGatewayId{12}};
    for (std::size_t k = 0; k < 2; ++k) {
      const json& g = gateways[k];
      CPPUNIT_ASSERT_EQUAL(GatewayId{k + 1}, g["id"].get<GatewayId>());
      CPPUNIT_ASSERT_EQUAL(detector[k], g["detectorId"].get<DetectorGatewayId>());
      CPPUNIT_ASSERT_EQUAL(std::string("NarrowPassage"), g["kind"].get<std::string>());
      CPPUNIT_ASSERT(g["door"].get<bool>());
      CPPUNIT_ASSERT_EQUAL(std::string(kNarrowPassageClass), g["label"].get<std::string>());
      CPPUNIT_ASSERT_EQUAL(g["label"], g["classes"][0]["name"]);
      CPPUNIT_ASSERT(!g["neutralised"].get<bool>());
      // The true door lines, not the drifted odometry frame the detector reported them in.
      for (const json& p : g["gatewayPoints"]) {
        CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, p[1].get<double>(), 0.01);
        CPPUNIT_ASSERT_DOUBLES_EQUAL(doorX[k], p[0].get<double>(), 0.46);
      }
      CPPUNIT_ASSERT_EQUAL(std::size_t(2), g["crossingPoints"].size());
      const Gateway& state = kernel_->state().gateways.at(GatewayId{k + 1});
      for (std::size_t side = 0; side < 2; ++side) {
        CPPUNIT_ASSERT_EQUAL(state.sides[side].region, g["sides"][side]["region"].get<RegionId>());
        CPPUNIT_ASSERT_EQUAL(state.sides[side].crossing, g["sides"][side]["crossing"].get<std::size_t>());
      }
      CPPUNIT_ASSERT(g["traversals"].get<std::size_t>() >= 2);
    }
  }

  void graphMatchesTheKernel() {
    const RgGraph graph = kernel_->graph();
    const json& nodes = doc_["graph"]["nodes"];
    const json& edges = doc_["graph"]["edges"];
    CPPUNIT_ASSERT_EQUAL(graph.nodes().size(), nodes.size());
    CPPUNIT_ASSERT_EQUAL(graph.edges().size(), edges.size());
    CPPUNIT_ASSERT_EQUAL(std::string("G1A"), nodes[0]["key"].get<std::string>());
    CPPUNIT_ASSERT_EQUAL(graph.nodes()[0].region, nodes[0]["region"].get<RegionId>());
    CPPUNIT_ASSERT_EQUAL(std::string("gateway"), edges[0]["kind"].get<std::string>());
    CPPUNIT_ASSERT_EQUAL(std::string("G1A"), edges[0]["from"].get<std::string>());
    CPPUNIT_ASSERT_EQUAL(std::string("G1B"), edges[0]["to"].get<std::string>());
    bool regionEdge = false;
    for (const json& e : edges) {
      regionEdge = regionEdge || e["kind"] == "region";
      CPPUNIT_ASSERT(e["cost"].get<double>() >= e["length"].get<double>());
    }
    CPPUNIT_ASSERT(regionEdge);  // the hallway joins both doors
  }

  void freespaceBitsDecodeToTheBitmap() {
    for (const json& r : doc_["regions"]) {
      const FreespaceBitmap& bitmap = kernel_->description(r["id"]).freespace;
      const json& f = r["freespace"];
      CPPUNIT_ASSERT_EQUAL(bitmap.width, f["width"].get<int>());
      CPPUNIT_ASSERT_EQUAL(bitmap.height, f["height"].get<int>());
      CPPUNIT_ASSERT_EQUAL(0.15, f["resolution"].get<double>());
      CPPUNIT_ASSERT_DOUBLES_EQUAL(bitmap.originM.x(), f["origin"][0].get<double>(), 5e-4 + 1e-9);
      const std::vector<std::uint8_t> bits = decodeBase64(f["bits"].get<std::string>());
      CPPUNIT_ASSERT(bits == bitmap.bytes);
      CPPUNIT_ASSERT_EQUAL((std::size_t(bitmap.width) * std::size_t(bitmap.height) + 7) / 8, bits.size());
    }
  }

  void sameMapGivesSameBytes() {
    const RgMappingKernel again = rgnav::testing::twoRoomMap();
    CPPUNIT_ASSERT(text_ == exportRgMapJson(snapshotOf(again)));
    CPPUNIT_ASSERT(text_ == exportRgMapJson(snapshotOf(*kernel_)));
    kernel_->nameRegion(RegionId{2}, "office \"A\"");
    const json named = json::parse(exportRgMapJson(snapshotOf(*kernel_)));
    CPPUNIT_ASSERT_EQUAL(std::string("office \"A\""), named["regions"][1]["name"].get<std::string>());
  }

  void valuesAreRounded() {
    // No number with more than 4 decimals (1 mm, 0.1 mrad, 1e-4) and no exponent notation.
    CPPUNIT_ASSERT(!std::regex_search(text_, std::regex("[0-9]\\.[0-9]{5,}")));
    CPPUNIT_ASSERT(!std::regex_search(text_, std::regex("[0-9][eE][-+]?[0-9]")));
    CPPUNIT_ASSERT_EQUAL('\n', text_.back());
  }

  // The invariant of the map's gateways: each one lies in a region (on one side at least).
  static void checkGatewaysInRegions(const json& doc) {
    for (const json& g : doc["gateways"])
      CPPUNIT_ASSERT_MESSAGE("gateway " + g["id"].dump() + " lies in no region",
                             !g["sides"][0]["region"].is_null() || !g["sides"][1]["region"].is_null());
    for (const json& g : doc["gatewayHypotheses"])
      CPPUNIT_ASSERT(g["sides"][0]["region"].is_null() && g["sides"][1]["region"].is_null());
    CPPUNIT_ASSERT_EQUAL(doc["gateways"].size(), doc["summary"]["gateways"].get<std::size_t>());
    CPPUNIT_ASSERT_EQUAL(doc["gatewayHypotheses"].size(), doc["summary"]["gatewayHypotheses"].get<std::size_t>());
  }

  void unreachedAreaIsAHypothesis() {
    checkGatewaysInRegions(doc_);
    CPPUNIT_ASSERT(doc_["gatewayHypotheses"].empty());
    // A crossing the detector reports at the end of the two-room tour, east of the hallway's end:
    // never traversed, so no region has taken it in.
    const std::vector<testing::KernelInput> inputs = testing::twoRoomTour().inputs();
    RgMappingKernel k = testing::mapped(inputs, inputs.size());
    const StoredScan& last = *std::find_if(inputs.rbegin(), inputs.rend(), [](const auto& in) { return in.scan.has_value(); })->scan;
    const auto odom = [](double x, double y) { return transformPoint(testing::kTourDrift, Eigen::Vector2d(x, y)); };
    GatewayEvent e;
    e.id = 1000;
    e.scanId = last.scan.id;
    GatewayRecord& r = e.gateway;
    r.id = DetectorGatewayId{99};
    r.kind = GatewayKind::HallwayArea;
    r.classes = {{"T-Junction", 0.9}};
    r.gatewayPoints = {odom(12, 2), odom(14, 2), odom(14, 0), odom(12, 0)};
    r.crossingPoints = {odom(11.5, 1), odom(13, 2.5), odom(14.5, 1), odom(13, -0.5)};
    r.widthM = 2.0;
    r.support = 2;
    r.firstScan = r.lastScan = last.scan.id;
    r.lastPose = last.scan.odometry;
    testing::feed(k, {std::nullopt, e, last.corrected});
    const json doc = json::parse(exportRgMapJson(snapshotOf(k)));
    checkGatewaysInRegions(doc);
    CPPUNIT_ASSERT_EQUAL(doc_["gateways"], doc["gateways"]);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), doc["gatewayHypotheses"].size());
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(99), doc["gatewayHypotheses"][0]["detectorId"].get<std::uint64_t>());
    CPPUNIT_ASSERT_EQUAL(doc_["graph"], doc["graph"]);
  }

  void fileIsWritten() {
    rgnav::testing::TempDir dir;
    writeRgMapJson(dir.file("map.json"), snapshot_);
    CPPUNIT_ASSERT(text_ == readCheckpoint(dir.file("map.json")).value());
    CPPUNIT_ASSERT_THROW(writeRgMapJson(dir.file("missing/map.json"), snapshot_), FileError);
  }

 private:
  std::unique_ptr<RgMappingKernel> kernel_;
  RgMapSnapshot snapshot_;
  std::string text_;
  json doc_;
};

CPPUNIT_TEST_SUITE_REGISTRATION(RgMapJsonTest);
