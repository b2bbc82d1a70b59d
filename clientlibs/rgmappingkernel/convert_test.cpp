// Round trips of the RGMappingKernel.idl conversions: a region with its description, a gateway,
// a graph, a path, the summary and an event batch, every field set.
#include <cppunit/extensions/HelperMacros.h>

#include "clientlibs/rgmappingkernel/convert.h"
#include "core/common/Errors.h"

using namespace rgnav;

class RgMappingKernelConvertTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RgMappingKernelConvertTest);
  CPPUNIT_TEST(regionRoundTrip);
  CPPUNIT_TEST(gatewayGraphPathRoundTrip);
  CPPUNIT_TEST(summaryAndEventsRoundTrip);
  CPPUNIT_TEST_SUITE_END();

 public:
  void regionRoundTrip() {
    RegionView r;
    r.summary = {RegionId{4}, "kitchen", {1.0, 2.0, 0.5}, 120, true, {GatewayId{2}, GatewayId{7}}};
    r.lines = {{{0, 0}, {3, 0}}, {{3, 0}, {3, 2}}};
    r.boxMin = {-0.1, -0.2};
    r.boxMax = {3.1, 2.2};
    r.freespace.resolutionM = 0.15;
    r.freespace.originM = {-0.15, -0.3};
    r.freespace.width = 22;
    r.freespace.height = 16;
    r.freespace.bytes = std::vector<std::uint8_t>(44, 0xA5);
    r.areaM2 = 6.1;
    r.centroid = {1.5, 1.0};
    r.majorAxisAngleRad = 0.01;
    r.majorVariance = 0.75;
    r.minorVariance = 0.33;
    r.mainDirections = {{0.0, 6.0, 0.6}, {M_PI / 2, 4.0, 0.4}};
    r.accuracyInlierShare = 0.97;
    r.accuracyRmsM = 0.012;
    r.completeness = 0.9;
    r.objects = {{{2.0, 1.5, 0.3}, 1.2, 0.6, 0.75, "cabinet"}, {{0.5, 0.4, 1.5}, 0.8, 0.8, 0.5, ""}};
    const RegionView back = fromIdl(toIdl(r));
    CPPUNIT_ASSERT(back.summary == r.summary);
    CPPUNIT_ASSERT(back.lines == r.lines);
    CPPUNIT_ASSERT(back.boxMin == r.boxMin && back.boxMax == r.boxMax);
    CPPUNIT_ASSERT(back.freespace.bytes == r.freespace.bytes);
    CPPUNIT_ASSERT_EQUAL(r.freespace.width, back.freespace.width);
    CPPUNIT_ASSERT_EQUAL(r.freespace.height, back.freespace.height);
    CPPUNIT_ASSERT(back.freespace.originM == r.freespace.originM);
    CPPUNIT_ASSERT_EQUAL(r.freespace.resolutionM, back.freespace.resolutionM);
    CPPUNIT_ASSERT_EQUAL(r.areaM2, back.areaM2);
    CPPUNIT_ASSERT(back.centroid == r.centroid);
    CPPUNIT_ASSERT_EQUAL(r.majorAxisAngleRad, back.majorAxisAngleRad);
    CPPUNIT_ASSERT_EQUAL(r.majorVariance, back.majorVariance);
    CPPUNIT_ASSERT_EQUAL(r.minorVariance, back.minorVariance);
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), back.mainDirections.size());
    CPPUNIT_ASSERT_EQUAL(r.mainDirections[1].angleRad, back.mainDirections[1].angleRad);
    CPPUNIT_ASSERT_EQUAL(r.accuracyInlierShare, back.accuracyInlierShare);
    CPPUNIT_ASSERT_EQUAL(r.accuracyRmsM, back.accuracyRmsM);
    CPPUNIT_ASSERT_EQUAL(r.completeness, back.completeness);
    CPPUNIT_ASSERT(back.objects == r.objects);
  }

  void gatewayGraphPathRoundTrip() {
    const GatewayView g{GatewayId{3}, DetectorGatewayId{9}, {{"Narrow-Passage", 0.8}}, true, false, {{1, 2}, {1, 3}},
                       {{0.5, 2.5}, {1.5, 2.5}}, RegionId{1}, RegionId{4}, 2, {0, kNoCrossing}};
    CPPUNIT_ASSERT(fromIdl(toIdl(g)) == g);
    GraphView graph;
    graph.nodes = {{GatewayId{3}, 0, RegionId{1}, {0.5, 2.5}}, {GatewayId{3}, 1, RegionId{4}, {1.5, 2.5}}};
    graph.edges = {{0, 1, GatewayId{3}, RegionId{}, 1.0, 1.5}, {0, 1, GatewayId{}, RegionId{4}, 0.5, 0.5}};
    const GraphView back = fromIdl(toIdl(graph));
    CPPUNIT_ASSERT(back.nodes == graph.nodes);
    CPPUNIT_ASSERT(back.edges == graph.edges);
    const PathView path{graph.nodes, 4.5, 4.0};
    const PathView pathBack = fromIdl(toIdl(path));
    CPPUNIT_ASSERT(pathBack.crossings == path.crossings);
    CPPUNIT_ASSERT_EQUAL(4.5, pathBack.costM);
    CPPUNIT_ASSERT_EQUAL(4.0, pathBack.lengthM);
  }

  void summaryAndEventsRoundTrip() {
    const MapSummaryView s{5, 6, 1, 2, 900, 40, RegionId{3}, true};
    CPPUNIT_ASSERT(fromIdl(toIdl(s)) == s);
    RgMapEventBatch b;
    b.events = {{7, RgMapEventKind::RegionsMerged, RegionId{2}, RegionId{5}, GatewayId{}, 311},
                {8, RgMapEventKind::GatewayNeutralised, RegionId{2}, RegionId{}, GatewayId{4}, 311},
                {9, RgMapEventKind::RegionsUnmerged, RegionId{2}, RegionId{5}, GatewayId{}, 318}};
    b.latestId = 9;
    b.lastScan = 320;
    b.endOfData = true;
    const RgMapEventBatch back = fromIdl(toIdl(b));
    CPPUNIT_ASSERT(back.events == b.events);
    CPPUNIT_ASSERT_EQUAL(b.latestId, back.latestId);
    CPPUNIT_ASSERT_EQUAL(b.lastScan, back.lastScan);
    CPPUNIT_ASSERT(back.endOfData);
    RGNav::RgMapEventBatch unknown = toIdl(b);
    unknown.events[0].kind = "SomethingNew";
    CPPUNIT_ASSERT_THROW(fromIdl(unknown), FormatError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(RgMappingKernelConvertTest);
