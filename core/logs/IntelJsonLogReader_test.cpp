// Tests IntelJsonLogReader on the real Intel JSON pair (raw odometry + corrected poses), its
// agreement with the CARMEN corrected log, bad JSON input, and openLog's choice of reader.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"
#include "core/logs/CarmenLogReader.h"
#include "core/logs/IntelJsonLogReader.h"
#include "core/logs/LogTestFiles.h"
#include "core/logs/OpenLog.h"

using rgnav::IntelJsonLogReader;
using rgnav::LaserScan;
using rgnav::OdometryReading;
using rgnav::testing::LogContents;
using rgnav::testing::TempDir;

namespace {

const std::string kRaw = "laser/derived/xiaofeng-intel_gfs.json.xz";
const std::string kCorrected = "laser/derived/xiaofeng-intel_corrected_log.json.xz";

rgnav::LogReaderOptions withCorrected(const std::string& path) {
  rgnav::LogReaderOptions options;
  options.correctedPosesPath = path;
  return options;
}

LogContents readPair(const std::string& raw, const std::string& corrected) {
  IntelJsonLogReader reader(raw, withCorrected(corrected));
  return rgnav::testing::readAll(reader);
}

LogContents readRealPair() {
  return readPair(rgnav::testing::sharedData(kRaw), rgnav::testing::sharedData(kCorrected));
}

// A JSON keyframe entry with three beams.
std::string entry(const std::string& stamp, double x) {
  return "\"" + stamp + "\": {\"range\": [1.0, 2.0, 81.83], \"x\": " + std::to_string(x) +
         ", \"y\": 0.5, \"theta\": 0.1}";
}

std::string mapOf(const std::string& entries) { return "{\"map\": {\n" + entries + "\n}}\n"; }

// Expects `check` to throw FormatError naming `file` and `line`.
template <typename Check>
void assertFormatError(const std::string& file, std::size_t line, Check check) {
  try {
    check();
  } catch (const rgnav::FormatError& e) {
    CPPUNIT_ASSERT_EQUAL(file, e.file());
    CPPUNIT_ASSERT_EQUAL(line, e.line());
    return;
  }
  CPPUNIT_FAIL("no FormatError for " + file);
}

}  // namespace

class IntelJsonLogReaderTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(IntelJsonLogReaderTest);
  CPPUNIT_TEST(realPairGives910Keyframes);
  CPPUNIT_TEST(correctedPosesMatchTheCarmenCorrectedLog);
  CPPUNIT_TEST(rawFileAloneUsesRawPoses);
  CPPUNIT_TEST(keysAreSortedNumerically);
  CPPUNIT_TEST(malformedEntriesAreSkippedWithTheirLines);
  CPPUNIT_TEST(mismatchedStampsAreFormatErrors);
  CPPUNIT_TEST(brokenJsonIsFormatError);
  CPPUNIT_TEST(openLogChoosesByName);
  CPPUNIT_TEST_SUITE_END();

 public:
  void realPairGives910Keyframes() {
    const LogContents log = readRealPair();
    CPPUNIT_ASSERT_EQUAL(std::size_t{910}, log.scans.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t{910}, log.odometry.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t{1820}, log.records.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < log.scans.size(); ++i) {
      const auto& reading = std::get<OdometryReading>(log.records[2 * i]);
      const auto& scan = std::get<LaserScan>(log.records[2 * i + 1]);
      CPPUNIT_ASSERT_EQUAL(rgnav::DataId{i + 1}, scan.id);
      CPPUNIT_ASSERT_EQUAL(rgnav::DataId{i + 1}, reading.id);
      CPPUNIT_ASSERT_EQUAL(reading.stamp, scan.stamp);
      CPPUNIT_ASSERT(reading.pose == scan.odometry);
      CPPUNIT_ASSERT(i == 0 || scan.stamp > log.scans[i - 1].stamp);
      CPPUNIT_ASSERT_EQUAL(std::size_t{180}, scan.ranges.size());
      CPPUNIT_ASSERT_DOUBLES_EQUAL(-M_PI / 2, scan.startAngle, 1e-12);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(M_PI / 180, scan.angleIncrement, 1e-12);
      differing += scan.odometry == scan.sensorPose ? 0 : 1;
    }
    CPPUNIT_ASSERT(differing > 900);
    const LaserScan& first = log.scans.front();
    CPPUNIT_ASSERT_DOUBLES_EQUAL(976052890.244111, first.stamp, 1e-6);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.698, first.odometry.x, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(-0.463373, first.odometry.theta, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.600266, first.sensorPose.x, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(-0.354665, first.sensorPose.theta, 1e-12);
    CPPUNIT_ASSERT_EQUAL(std::size_t{4172}, log.stats.noReturnRanges);
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, log.stats.malformedLines);
  }

  // The JSON corrected poses are the poses of the CARMEN corrected log, once that log's scans
  // (a few are written out of stamp order) are sorted by stamp.
  void correctedPosesMatchTheCarmenCorrectedLog() {
    const LogContents json = readRealPair();
    rgnav::CarmenLogReader carmenReader(
        rgnav::testing::sharedData("laser/corrected/intel-corrected.log.gz"));
    LogContents carmen = rgnav::testing::readAll(carmenReader);
    std::stable_sort(carmen.scans.begin(), carmen.scans.end(),
                     [](const auto& a, const auto& b) { return a.stamp < b.stamp; });
    constexpr double kLoggerEpoch = 976052857.3373;  // SOURCES.md: relative + this = absolute
    for (std::size_t i = 0; i < json.scans.size(); ++i) {
      const LaserScan& a = json.scans[i];
      const LaserScan& b = carmen.scans.at(i);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(a.stamp, b.stamp + kLoggerEpoch, 0.01);
      CPPUNIT_ASSERT(a.sensorPose == b.sensorPose);
      CPPUNIT_ASSERT(std::equal(a.ranges.begin(), a.ranges.end(), b.ranges.begin(),
                                b.ranges.end()));
    }
  }

  void rawFileAloneUsesRawPoses() {
    IntelJsonLogReader reader(rgnav::testing::sharedData(kRaw));
    const LogContents log = rgnav::testing::readAll(reader);
    CPPUNIT_ASSERT_EQUAL(std::size_t{910}, log.scans.size());
    for (const auto& scan : log.scans) {
      CPPUNIT_ASSERT(scan.sensorPose == scan.odometry);
    }
  }

  void keysAreSortedNumerically() {
    TempDir dir;
    rgnav::testing::writeFile(dir.file("raw.json"),
                              mapOf(entry("10.5", 1) + ",\n" + entry("9.25", 2) + ",\n" +
                                    entry("100", 3)));
    IntelJsonLogReader reader(dir.file("raw.json"));
    const LogContents log = rgnav::testing::readAll(reader);
    CPPUNIT_ASSERT_EQUAL(std::size_t{3}, log.scans.size());
    CPPUNIT_ASSERT_EQUAL(9.25, log.scans[0].stamp);
    CPPUNIT_ASSERT_EQUAL(10.5, log.scans[1].stamp);
    CPPUNIT_ASSERT_EQUAL(100.0, log.scans[2].stamp);
    CPPUNIT_ASSERT_EQUAL(2.0, log.scans[0].odometry.x);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(M_PI / 2, log.scans[0].angleIncrement, 1e-12);
    CPPUNIT_ASSERT(std::isinf(log.scans[0].ranges[2]));
  }

  void malformedEntriesAreSkippedWithTheirLines() {
    TempDir dir;
    const std::string path = dir.file("raw.json");
    rgnav::testing::writeFile(
        path, mapOf(entry("1", 1) + ",\n\"2\": {\"range\": [1], \"y\": 0, \"theta\": 0},\n" +
                    "\"abc\": {\"range\": [1], \"x\": 0, \"y\": 0, \"theta\": 0},\n" +
                    "\"4\": {\"range\": [\"near\"], \"x\": 0, \"y\": 0, \"theta\": 0},\n" +
                    "\"5\": {\"range\": [], \"x\": 0, \"y\": 0, \"theta\": 0},\n" +
                    "\"6\": 7,\n" + entry("7", 2)));
    IntelJsonLogReader reader(path);
    const LogContents log = rgnav::testing::readAll(reader);
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, log.scans.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t{5}, log.stats.malformedLines);
    CPPUNIT_ASSERT_EQUAL(std::size_t{5}, log.stats.problems.size());
    for (std::size_t i = 0; i < 5; ++i) {
      const std::string prefix = path + ":" + std::to_string(i + 3) + ": keyframe ";
      CPPUNIT_ASSERT_EQUAL(prefix, log.stats.problems[i].substr(0, prefix.size()));
    }
  }

  void mismatchedStampsAreFormatErrors() {
    TempDir dir;
    const std::string raw = dir.file("raw.json");
    const std::string other = dir.file("other.json");
    const std::string longer = dir.file("longer.json");
    rgnav::testing::writeFile(raw, mapOf(entry("1.5", 1) + ",\n" + entry("2.5", 2)));
    rgnav::testing::writeFile(other, mapOf(entry("1.5", 1) + ",\n" + entry("2.75", 2)));
    rgnav::testing::writeFile(longer, mapOf(entry("1.5", 1) + ",\n" + entry("2.5", 2) + ",\n" +
                                            entry("3.5", 3)));
    assertFormatError(other, 3, [&] { IntelJsonLogReader(raw, withCorrected(other)); });
    assertFormatError(longer, 4, [&] { IntelJsonLogReader(raw, withCorrected(longer)); });
    CPPUNIT_ASSERT_THROW(IntelJsonLogReader(longer, withCorrected(raw)), rgnav::FormatError);
    CPPUNIT_ASSERT_THROW(IntelJsonLogReader(raw, withCorrected(dir.file("missing.json"))),
                         rgnav::FileError);
  }

  void brokenJsonIsFormatError() {
    TempDir dir;
    const std::string cut = dir.file("cut.json");
    rgnav::testing::writeFile(cut, "{\"map\": {\n" + entry("1", 1) + ",\n\"2\": {\"range\": [1,");
    assertFormatError(cut, 3, [&] { IntelJsonLogReader{cut}; });
    const std::string wrong = dir.file("wrong.json");
    rgnav::testing::writeFile(wrong, "[1, 2]\n");
    assertFormatError(wrong, 1, [&] { IntelJsonLogReader{wrong}; });
    const std::string xz = rgnav::testing::xzCompress(mapOf(entry("1", 1) + ",\n" + entry("2", 2)));
    const std::string truncated = dir.file("cut.json.xz");
    rgnav::testing::writeFile(truncated, xz.substr(0, xz.size() - 20));
    CPPUNIT_ASSERT_THROW(IntelJsonLogReader{truncated}, rgnav::FormatError);
    const std::string garbage = dir.file("garbage.json");
    rgnav::testing::writeFile(garbage, std::string("\x01\xff{{\0", 5));
    assertFormatError(garbage, 1, [&] { IntelJsonLogReader{garbage}; });
    CPPUNIT_ASSERT_THROW(IntelJsonLogReader{dir.path()}, rgnav::FileError);
  }

  void openLogChoosesByName() {
    CPPUNIT_ASSERT(rgnav::isJsonLogPath("a/b.json"));
    CPPUNIT_ASSERT(rgnav::isJsonLogPath("b.JSON.xz"));
    CPPUNIT_ASSERT(rgnav::isJsonLogPath("b.json.gz"));
    CPPUNIT_ASSERT(!rgnav::isJsonLogPath("b.log.gz"));
    CPPUNIT_ASSERT(!rgnav::isJsonLogPath("json"));
    CPPUNIT_ASSERT(!rgnav::isJsonLogPath("b.json.bz2"));
    const auto source = rgnav::openLog(rgnav::testing::sharedData(kRaw),
                                       withCorrected(rgnav::testing::sharedData(kCorrected)));
    CPPUNIT_ASSERT(dynamic_cast<IntelJsonLogReader*>(source.get()) != nullptr);
    const LogContents log = rgnav::testing::readAll(*source);
    CPPUNIT_ASSERT_EQUAL(std::size_t{910}, log.scans.size());
    CPPUNIT_ASSERT(!(log.scans[0].sensorPose == log.scans[0].odometry));
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(IntelJsonLogReaderTest);
