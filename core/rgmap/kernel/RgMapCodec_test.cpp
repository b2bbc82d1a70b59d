// Tests the RG Mapping Kernel's checkpoints and its global consistency check: a kernel resumed
// from a checkpoint taken anywhere in a tour ends with exactly the bytes of one that never
// stopped (and the same descriptions); laser ranges of every kind survive the trip; the scan
// journal may hold more than the map (a crash between append and map) and a part of a line, but
// not less; damaged or inconsistent checkpoints are format errors; deliberately broken states are
// reported by checkConsistency, one message per violation; merges on request stay revertible
// across a checkpoint.
#include "core/rgmap/kernel/RgMapCodec.h"

#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <iterator>
#include <limits>

#include "core/common/Errors.h"
#include "core/rgmap/kernel/RgMapConsistency.h"
#include "core/rgmap/kernel/testing/SyntheticTour.h"

using namespace rgnav;
using rgnav::testing::feedChecked;
using rgnav::testing::KernelInput;
using rgnav::testing::mapped;

namespace {

bool mentions(const std::vector<std::string>& violations, const std::string& what) {
  for (const std::string& v : violations)
    if (v.find(what) != std::string::npos) return true;
  return false;
}

RgMapState roundTrip(const RgMapState& state) {
  return deserializeRgMap(serializeRgMap(state), scanJournalLines(state));
}

void expectFormatError(const std::string& text, const std::string& journal = "") {
  CPPUNIT_ASSERT_THROW(deserializeRgMap(text, journal), FormatError);
}

// `text` with the first occurrence of `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  CPPUNIT_ASSERT(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace

class RgMapCodecTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RgMapCodecTest);
  CPPUNIT_TEST(resumedKernelEndsIdentically);
  CPPUNIT_TEST(resumedRingClosesTheSameLoop);
  CPPUNIT_TEST(rangesOfEveryKindSurvive);
  CPPUNIT_TEST(doorAliasesSurvive);
  CPPUNIT_TEST(poseRevisionSurvives);
  CPPUNIT_TEST(revertibleMergesSurvive);
  CPPUNIT_TEST(journalMayHoldMoreButNotLess);
  CPPUNIT_TEST(damagedCheckpointsAreFormatErrors);
  CPPUNIT_TEST(brokenStatesAreReported);
  CPPUNIT_TEST_SUITE_END();

 public:
  void poseRevisionSurvives() {
    const std::vector<KernelInput> inputs = rgnav::testing::twoRoomTour().inputs();
    RgMappingKernel kernel = mapped(inputs, inputs.size());
    std::vector<CorrectedPose> poses;
    for (const auto& [id, scan] : kernel.state().scans) poses.push_back({id, scan.corrected});
    kernel.revisePoses(poses, 12);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{12}, roundTrip(kernel.state()).lastPoseRevision);
  }

  // A merge on request made before a restart is undone after it, to the same map; a checkpoint
  // written before merges could be undone reads with none.
  void revertibleMergesSurvive() {
    const std::vector<KernelInput> inputs = rgnav::testing::twoRoomTour().inputs();
    RgMappingKernel kernel = mapped(inputs, inputs.size());
    const std::string older = replaced(serializeRgMap(kernel.state()), "\"revertibleMerges\":[],", "");
    CPPUNIT_ASSERT(deserializeRgMap(older, scanJournalLines(kernel.state())).revertibleMerges.empty());
    kernel.nameRegion(RegionId{3}, "lab");
    kernel.mergeRegions(RegionId{2}, RegionId{3}, true);

    const RgMapState saved = roundTrip(kernel.state());
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), saved.revertibleMerges.size());
    CPPUNIT_ASSERT(saved.revertibleMerges == kernel.state().revertibleMerges);
    RgMappingKernel resumed({}, saved);
    CPPUNIT_ASSERT_EQUAL(RegionId{3}, resumed.unmergeRegions(RegionId{2}));
    kernel.unmergeRegions(RegionId{2});
    CPPUNIT_ASSERT_EQUAL(serializeRgMap(kernel.state()), serializeRgMap(resumed.state()));
    CPPUNIT_ASSERT_EQUAL(RegionId{3}, *resumed.regionByName("lab"));
  }

  void resumedKernelEndsIdentically() {
    const std::vector<KernelInput> inputs = rgnav::testing::twoRoomTour().inputs();
    const RgMappingKernel straight = mapped(inputs, inputs.size());
    const std::string expected = serializeRgMap(straight.state());
    for (std::size_t stop : {std::size_t(1), inputs.size() / 3, inputs.size() / 2, inputs.size() - 1}) {
      const RgMappingKernel first = mapped(inputs, stop);
      RgMappingKernel resumed({}, roundTrip(first.state()));
      CPPUNIT_ASSERT_EQUAL(first.state().lastScanId, resumed.state().lastScanId);
      CPPUNIT_ASSERT_EQUAL(first.state().lastGatewayEventId, resumed.state().lastGatewayEventId);
      CPPUNIT_ASSERT_EQUAL(std::string(), feedChecked(resumed, inputs, stop, inputs.size()));
      CPPUNIT_ASSERT_EQUAL_MESSAGE("stopped after input " + std::to_string(stop), expected,
                                   serializeRgMap(resumed.state()));
      for (const auto& [id, region] : straight.state().regions) {
        const RegionDescription& a = straight.description(id);
        const RegionDescription& b = resumed.description(id);
        CPPUNIT_ASSERT(a.freespace.bytes == b.freespace.bytes);
        CPPUNIT_ASSERT(a.boundingBox.isApprox(b.boundingBox, 0.0));
        CPPUNIT_ASSERT_EQUAL(straight.lineMap(id).lineCount(), resumed.lineMap(id).lineCount());
      }
    }
  }

  void resumedRingClosesTheSameLoop() {
    const std::vector<KernelInput> inputs = rgnav::testing::ringTour().inputs();
    const RgMappingKernel straight = mapped(inputs, inputs.size());
    RgMappingKernel first = mapped(inputs, inputs.size() / 2);
    first.nameRegion(RegionId{2}, "east corridor");
    RgMappingKernel resumed({}, roundTrip(first.state()));
    CPPUNIT_ASSERT_EQUAL(std::string(), feedChecked(resumed, inputs, inputs.size() / 2, inputs.size()));
    CPPUNIT_ASSERT_EQUAL(RegionId(1), *resumed.regionByName("east corridor"));  // merged: the name stays
    CPPUNIT_ASSERT(resumed.state().gateways.at(GatewayId{1}).neutralised);
    // The structure of a run without the stop.
    CPPUNIT_ASSERT(straight.state().gateways == resumed.state().gateways);
    CPPUNIT_ASSERT(straight.state().regions.at(RegionId{1}).scans == resumed.state().regions.at(RegionId{1}).scans);
  }

  void rangesOfEveryKindSurvive() {
    RgMapState s;
    LaserScan scan;
    scan.id = 1;
    scan.stamp = 1234.5678901234;
    scan.angleIncrement = M_PI / 360;
    scan.maxRange = 30.0;
    scan.ranges = {0.1f,
                   1.2345678f,
                   3.0e-7f,
                   29.999998f,
                   std::numeric_limits<float>::max(),
                   LaserScan::kNoReturn,
                   -LaserScan::kNoReturn,
                   LaserScan::kInvalid,
                   std::numeric_limits<float>::denorm_min(),
                   0.0f};
    s.scans.emplace(1, StoredScan{scan, {1, 2, 3}});
    s.regions.emplace(RegionId{1}, Region{RegionId{1}, {}, {1}, {}, {}, false, {}});
    s.current = RegionId{1};
    s.nextRegionId = RegionId{2};
    s.lastScanId = 1;
    const std::string text = serializeRgMap(s);
    const std::string line = scanJournalLines(s);
    const RgMapState back = deserializeRgMap(text, line);
    const std::vector<float>& r = back.scans.at(1).scan.ranges;
    CPPUNIT_ASSERT_EQUAL(scan.ranges.size(), r.size());
    for (std::size_t i = 0; i < r.size(); ++i)
      CPPUNIT_ASSERT(std::isnan(scan.ranges[i]) ? std::isnan(r[i]) : r[i] == scan.ranges[i]);
    CPPUNIT_ASSERT(line.find("1.2345678,") != std::string::npos);  // the float's shortest form
    CPPUNIT_ASSERT_EQUAL(text, serializeRgMap(back));
    CPPUNIT_ASSERT_EQUAL(line, scanJournalLines(back));
  }

  void doorAliasesSurvive() {
    const std::vector<KernelInput> inputs = rgnav::testing::twoRoomTour().inputs();
    RgMapState s = mapped(inputs, inputs.size()).state();
    s.gateways.at(GatewayId{1}).aliases = {DetectorGatewayId{111}, DetectorGatewayId{112}};
    const RgMapState back = roundTrip(s);
    CPPUNIT_ASSERT(back.gateways == s.gateways);
  }

  void journalMayHoldMoreButNotLess() {
    const std::vector<KernelInput> inputs = rgnav::testing::twoRoomTour().inputs();
    const RgMapState earlier = mapped(inputs, inputs.size() / 2).state();
    const RgMapState later = mapped(inputs, inputs.size()).state();
    const std::string map = serializeRgMap(earlier);
    // A crash after appending the later scans, in the middle of the last line: the earlier map.
    const std::string ahead = scanJournalLines(later);
    const RgMapState back = deserializeRgMap(map, ahead.substr(0, ahead.size() - 20));
    CPPUNIT_ASSERT(back.scans == earlier.scans);
    CPPUNIT_ASSERT_EQUAL(map, serializeRgMap(back));
    // A scan appended twice (a map write failed after the append) is read once.
    const std::string twice = scanJournalLines(earlier) + scanJournalLines(earlier, std::prev(earlier.scans.end(), 2)->first);
    CPPUNIT_ASSERT(deserializeRgMap(map, twice).scans == earlier.scans);
    // A journal without the map's last scan.
    const std::string journal = scanJournalLines(earlier);
    const std::string shorter = journal.substr(0, journal.rfind('\n', journal.size() - 2) + 1);
    try {
      deserializeRgMap(map, shorter);
      CPPUNIT_FAIL("a journal without a scan of the map was taken");
    } catch (const FormatError& e) {
      CPPUNIT_ASSERT(std::string(e.what()).find("is not in the scan journal") != std::string::npos);
    }
  }

  void damagedCheckpointsAreFormatErrors() {
    const std::vector<KernelInput> inputs = rgnav::testing::twoRoomTour().inputs();
    const RgMapState state = mapped(inputs, inputs.size()).state();
    const std::string good = serializeRgMap(state), journal = scanJournalLines(state);
    CPPUNIT_ASSERT_NO_THROW(deserializeRgMap(good, journal));
    expectFormatError(good.substr(0, good.size() / 2), journal);
    expectFormatError("", journal);
    expectFormatError("[1, 2, 3]", journal);
    expectFormatError(good, "{\"id\": 1}\n");  // a journal line without laser data
    expectFormatError(replaced(good, "\"version\":4", "\"version\":3"), journal);
    expectFormatError(replaced(good, "\"rgnav-rg-map\"", "\"rgnav-gateway-detection\""), journal);
    expectFormatError(replaced(good, "\"RegionCreated\"", "\"RegionBorn\""), journal);
    expectFormatError(replaced(good, "\"kind\":\"NarrowPassage\"", "\"kind\":\"Staircase\""), journal);
    expectFormatError(replaced(good, "\"neutralised\":false", "\"neutralised\":true"), journal);  // inconsistent
    expectFormatError(replaced(good, "\"gateways\":[1,2]", "\"gateways\":[1]"), journal);  // one reference lost
    try {
      deserializeRgMap(replaced(good, "\"gateways\":[1,2]", "\"gateways\":[1]"), journal);
    } catch (const FormatError& e) {
      CPPUNIT_ASSERT(std::string(e.what()).find("gateway 2") != std::string::npos);
    }
  }

  void brokenStatesAreReported() {
    const std::vector<KernelInput> inputs = rgnav::testing::twoRoomTour().inputs();
    const RgMappingKernel k = mapped(inputs, inputs.size());
    CPPUNIT_ASSERT(k.checkConsistency().empty());
    const RgMapState good = k.state();

    RgMapState s = good;
    s.regions.at(RegionId{2}).gateways.erase(GatewayId{1});  // room 1 forgets its door
    CPPUNIT_ASSERT(mentions(checkConsistency(s), "gateway 1 side B names region 2, which does not list it"));

    s = good;
    s.regions.at(RegionId{3}).gateways.insert(GatewayId{1});  // room 2 claims room 1's door
    CPPUNIT_ASSERT(mentions(checkConsistency(s), "region 3 lists gateway 1, which does not name it"));

    s = good;
    s.gateways.at(GatewayId{2}).aliases = {s.gateways.at(GatewayId{1}).record.id};  // door 2 also answers to door 1's detector ID
    CPPUNIT_ASSERT(mentions(checkConsistency(s), "gateway 2: detector gateway 11 is mapped twice"));

    s = good;
    s.gateways.at(GatewayId{2}).neutralised = true;
    CPPUNIT_ASSERT(mentions(checkConsistency(s), "gateway 2: neutralised but joins two sides"));

    s = good;
    s.gateways.at(GatewayId{2}).sides[kSideB].region = RegionId{1};  // both sides the hallway, not flagged (and room 2 still lists it)
    const std::vector<std::string> violations = checkConsistency(s);
    CPPUNIT_ASSERT(mentions(violations, "gateway 2: the same region on both sides but not neutralised"));
    CPPUNIT_ASSERT(mentions(violations, "region 3 lists gateway 2, which does not name it"));

    s = good;
    s.regions.at(RegionId{2}).scans.push_back(s.regions.at(RegionId{1}).scans.back() + 100000);                      // a scan never stored
    s.regions.at(RegionId{3}).scans.insert(s.regions.at(RegionId{3}).scans.begin(), s.regions.at(RegionId{1}).scans.front());  // in two regions
    const std::vector<std::string> scans = checkConsistency(s);
    CPPUNIT_ASSERT(mentions(scans, "is not stored"));
    CPPUNIT_ASSERT(mentions(scans, "lies in 2 regions"));

    s = good;
    s.regions.at(RegionId{3}).scans.clear();  // an empty region the robot is not in
    s.scans.clear();
    s.regions.at(RegionId{1}).scans.clear();
    s.regions.at(RegionId{2}).scans.clear();
    const std::vector<std::string> empty = checkConsistency(s);
    CPPUNIT_ASSERT(mentions(empty, "region 3: empty"));
    CPPUNIT_ASSERT(!mentions(empty, "region 1: empty"));  // the current one may be

    s = good;
    s.regions.at(RegionId{3}).name = s.regions.at(RegionId{2}).name = "office";
    s.current = RegionId{42};
    s.events[3].id = 99;
    const std::vector<std::string> rest = checkConsistency(s);
    CPPUNIT_ASSERT(mentions(rest, "name \"office\" is taken by region 2"));
    CPPUNIT_ASSERT(mentions(rest, "the current region 42 does not exist"));
    CPPUNIT_ASSERT(mentions(rest, "event 99 out of sequence"));

    CPPUNIT_ASSERT_THROW(RgMappingKernel({}, s), InvalidArgumentError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(RgMapCodecTest);
