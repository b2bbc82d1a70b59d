// Tests CarmenLogReader on bad input written to temporary files: garbled lines among good ones,
// odd range values, absurd beam counts, random bytes, a 10 MB line, truncated compressed logs and
// paths that cannot be opened. Each case must end in a typed error or a counted skip, and the
// skips and an early end are described by kind with the first file:line of each.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <random>
#include <string>

#include "core/common/Errors.h"
#include "core/logs/CarmenLogReader.h"
#include "core/logs/LogTestFiles.h"
#include "core/logs/OpenLog.h"

using rgnav::CarmenLogReader;
using rgnav::testing::LogContents;
using rgnav::testing::TempDir;

namespace {

const std::string kOdom = "ODOM 1 2 0.5 0.1 0.2 0 10.5 host 10.5\n";

// A FLASER line with the given beam field text and count.
std::string flaser(std::size_t count, const std::string& beams, double stamp = 11.0) {
  return "FLASER " + std::to_string(count) + " " + beams + " 1 2 0.5 1.1 2.1 0.6 " +
         std::to_string(stamp) + " host " + std::to_string(stamp) + "\n";
}

std::string robotLaser(const std::string& counts) {
  return "ROBOTLASER1 0 -1.57 3.14 0.5 50 0.1 0 " + counts +
         " 1 2 0.5 1.1 2.1 0.6 0 0 0 0 0 12 host 12\n";
}

LogContents readText(const TempDir& dir, const std::string& text,
                     const rgnav::LogReaderOptions& options = {}) {
  const std::string path = dir.file("test.log");
  rgnav::testing::writeFile(path, text);
  CarmenLogReader reader(path, options);
  return rgnav::testing::readAll(reader);
}

// A log of `scans` FLASER lines, each followed by two ODOM lines.
std::string generatedLog(std::size_t scans) {
  std::mt19937 random(3);
  std::string text;
  for (std::size_t i = 0; i < scans; ++i) {
    std::string beams;
    for (int b = 0; b < 180; ++b) {
      beams += std::to_string(random() % 8000 / 1000.0) + " ";
    }
    text += flaser(180, beams, static_cast<double>(i)) + kOdom + kOdom;
  }
  return text;
}

bool startsWith(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

// Reads a damaged compressed log: records come until a FormatError naming the file, which the
// statistics keep as the truncation, reported for people.
void assertTruncatedLogFails(const std::string& path) {
  CarmenLogReader reader(path);
  try {
    while (reader.next()) {
    }
  } catch (const rgnav::FormatError& e) {
    const rgnav::LogStats& stats = reader.stats();
    CPPUNIT_ASSERT_EQUAL(path, e.file());
    CPPUNIT_ASSERT_EQUAL(stats.lines + 1, e.line());
    CPPUNIT_ASSERT(stats.scans > 10);
    CPPUNIT_ASSERT(stats.truncated && !stats.wholeLog());
    CPPUNIT_ASSERT_EQUAL(std::string(e.what()), stats.truncation);
    CPPUNIT_ASSERT_EQUAL(std::string("skipped_lines=0 truncated=yes"), rgnav::skipFigures(stats));
    const std::vector<std::string> described = rgnav::describeSkips(stats);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, described.size());
    CPPUNIT_ASSERT_EQUAL("the log ends early, the rest is lost: " + std::string(e.what()), described[0]);
    return;
  }
  CPPUNIT_FAIL("no FormatError for " + path);
}

}  // namespace

class CarmenBadInputTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(CarmenBadInputTest);
  CPPUNIT_TEST(garbledLinesAreSkippedWithTheirLineNumbers);
  CPPUNIT_TEST(rangesFollowRep117);
  CPPUNIT_TEST(maxRangeIsAnOption);
  CPPUNIT_TEST(absurdBeamCountsAreMalformed);
  CPPUNIT_TEST(randomBytesAreCountedNotRead);
  CPPUNIT_TEST(tenMegabyteLineIsCountedAsOverLong);
  CPPUNIT_TEST(truncatedGzipLogThrowsAfterGoodRecords);
  CPPUNIT_TEST(truncatedXzLogThrowsAfterGoodRecords);
  CPPUNIT_TEST(skipsAreDescribedByKindWithTheirFirstLine);
  CPPUNIT_TEST(wholeLogHasNothingToDescribe);
  CPPUNIT_TEST(cutAndGarbledRealLogIsReported);
  CPPUNIT_TEST(missingFileAndDirectoryFailAtOpen);
  CPPUNIT_TEST(badOptionsAreRejected);
  CPPUNIT_TEST_SUITE_END();

 public:
  void garbledLinesAreSkippedWithTheirLineNumbers() {
    TempDir dir;
    const LogContents log = readText(
        dir, flaser(3, "1 2 3") + kOdom + flaser(3, "1 abc 3") + kOdom + "ODOM 1 2\n" +
                 "PARAM robot_x 1 nohost 0\n# a comment\n\nFOO 1 2\nNEFF 3\n" +
                 flaser(3, "4 5 6") + "ROBOTLASER1 0 x\n" + "FLASER 3 1 2 3 1 2 nan 1 2 3 4 h 5\n");
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, log.scans.size());
    CPPUNIT_ASSERT_EQUAL(rgnav::DataId{2}, log.scans[1].id);
    CPPUNIT_ASSERT_EQUAL(4.0f, log.scans[1].ranges[0]);
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, log.odometry.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t{13}, log.stats.lines);
    CPPUNIT_ASSERT_EQUAL(std::size_t{4}, log.stats.malformedLines);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, log.stats.unknownMessages);
    CPPUNIT_ASSERT_EQUAL(std::size_t{4}, log.stats.problems.size());
    const std::string path = dir.file("test.log");
    CPPUNIT_ASSERT(startsWith(log.stats.problems[0], path + ":3: FLASER: range 2 is not a number"));
    CPPUNIT_ASSERT(startsWith(log.stats.problems[1], path + ":5: ODOM: expected 10 fields"));
    CPPUNIT_ASSERT(startsWith(log.stats.problems[2], path + ":12: ROBOTLASER1: "));
    CPPUNIT_ASSERT(
        startsWith(log.stats.problems[3], path + ":13: FLASER: laser theta is not finite"));
  }

  void rangesFollowRep117() {
    TempDir dir;
    const LogContents log = readText(dir, flaser(8, "nan inf -1 -inf 81.83 80 2.5 0"));
    const auto& ranges = log.scans.at(0).ranges;
    for (int i = 0; i < 4; ++i) {
      CPPUNIT_ASSERT(std::isnan(ranges[i]));
    }
    CPPUNIT_ASSERT(std::isinf(ranges[4]) && ranges[4] > 0);
    CPPUNIT_ASSERT(std::isinf(ranges[5]) && ranges[5] > 0);
    CPPUNIT_ASSERT_EQUAL(2.5f, ranges[6]);
    CPPUNIT_ASSERT_EQUAL(0.0f, ranges[7]);
    CPPUNIT_ASSERT_EQUAL(std::size_t{4}, log.stats.droppedRanges);
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, log.stats.noReturnRanges);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(M_PI / 7, log.scans[0].angleIncrement, 1e-12);
  }

  void maxRangeIsAnOption() {
    TempDir dir;
    rgnav::LogReaderOptions options;
    options.maxRange = 2.0;
    const LogContents log = readText(dir, flaser(3, "1.9 2.0 2.5"), options);
    CPPUNIT_ASSERT_EQUAL(1.9f, log.scans.at(0).ranges[0]);
    CPPUNIT_ASSERT(std::isinf(log.scans[0].ranges[1]));
    CPPUNIT_ASSERT_EQUAL(2.0, log.scans[0].maxRange);
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, log.stats.noReturnRanges);
  }

  void absurdBeamCountsAreMalformed() {
    TempDir dir;
    const LogContents log = readText(
        dir, flaser(99999, "1 2 3") + flaser(100001, "1 2 3") + "FLASER 18446744073709551615 1\n" +
                 "FLASER 99999999999999999999999999 1 2\nFLASER -5 1 2\nFLASER 2.5 1 2\n" +
                 flaser(0, "") + robotLaser("1000000000 1 0") + robotLaser("1 1 4000000000") +
                 robotLaser("2 1 0") + robotLaser("1 1 0"));
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, log.scans.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t{10}, log.stats.malformedLines);
    CPPUNIT_ASSERT_EQUAL(0.5, log.scans[0].angleIncrement);
    CPPUNIT_ASSERT_EQUAL(50.0, log.scans[0].maxRange);
    for (const auto& problem : log.stats.problems) {
      CPPUNIT_ASSERT(problem.size() < 200);
    }
  }

  void randomBytesAreCountedNotRead() {
    TempDir dir;
    std::string bytes = rgnav::testing::randomBytes(1 << 20, 11);
    bytes[0] = 'G';
    rgnav::LogReaderOptions options;
    options.maxLineLength = 4096;
    const LogContents log = readText(dir, bytes, options);
    CPPUNIT_ASSERT(log.scans.empty() && log.odometry.empty());
    CPPUNIT_ASSERT(log.stats.lines > 1000);
    CPPUNIT_ASSERT(log.stats.malformedLines > 1000);
    CPPUNIT_ASSERT_EQUAL(rgnav::LogStats::kMaxProblems, log.stats.problems.size());
  }

  void tenMegabyteLineIsCountedAsOverLong() {
    TempDir dir;
    const std::string huge = flaser(3, "1 2 3" + std::string(10 << 20, ' ') + "4");
    const LogContents log = readText(dir, kOdom + huge + kOdom);
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, log.odometry.size());
    CPPUNIT_ASSERT_EQUAL(rgnav::DataId{2}, log.odometry[1].id);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, log.stats.overLongLines);
    CPPUNIT_ASSERT_EQUAL(std::size_t{3}, log.stats.lines);
    CPPUNIT_ASSERT(startsWith(log.stats.problems.at(0), dir.file("test.log") + ":2: line longer"));
  }

  void truncatedGzipLogThrowsAfterGoodRecords() {
    TempDir dir;
    const std::string gz = rgnav::testing::gzipCompress(generatedLog(2000));
    rgnav::testing::writeFile(dir.file("cut.log.gz"), gz.substr(0, gz.size() / 2));
    assertTruncatedLogFails(dir.file("cut.log.gz"));
  }

  void truncatedXzLogThrowsAfterGoodRecords() {
    TempDir dir;
    const std::string xz = rgnav::testing::xzCompress(generatedLog(2000));
    rgnav::testing::writeFile(dir.file("cut.log.xz"), xz.substr(0, xz.size() / 2));
    assertTruncatedLogFails(dir.file("cut.log.xz"));
  }

  void skipsAreDescribedByKindWithTheirFirstLine() {
    TempDir dir;
    rgnav::LogReaderOptions options;
    options.maxLineLength = 200;
    const LogContents log = readText(dir,
                                     kOdom + flaser(3, "1 x 3") + flaser(3, "1 2 3" + std::string(300, ' ')) +
                                         flaser(3, "1 2 3") + "ODOM 1\n",
                                     options);
    const std::string path = dir.file("test.log");
    CPPUNIT_ASSERT_EQUAL(std::size_t{3}, log.stats.skippedLines());
    CPPUNIT_ASSERT(!log.stats.wholeLog());
    CPPUNIT_ASSERT_EQUAL(std::string("skipped_lines=3 truncated=no"), rgnav::skipFigures(log.stats));
    const std::vector<std::string> described = rgnav::describeSkips(log.stats);
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, described.size());
    CPPUNIT_ASSERT_MESSAGE(described[0],
                           startsWith(described[0], "2 malformed lines skipped, the first " + path + ":2: FLASER: "));
    CPPUNIT_ASSERT_EQUAL("1 over-long lines skipped, the first " + path + ":3: line longer than 200 bytes, skipped",
                         described[1]);
  }

  void wholeLogHasNothingToDescribe() {
    TempDir dir;
    const LogContents log = readText(dir, kOdom + flaser(3, "1 2 3") + "FOO 1\n");
    CPPUNIT_ASSERT(log.stats.wholeLog());
    CPPUNIT_ASSERT(rgnav::describeSkips(log.stats).empty());
    CPPUNIT_ASSERT_EQUAL(std::string("skipped_lines=0 truncated=no"), rgnav::skipFigures(log.stats));
  }

  // The first 3000 lines of the Intel log, every other FLASER line cut in half, gzipped and the
  // compressed stream cut at two thirds: the skips and the early end are both reported.
  void cutAndGarbledRealLogIsReported() {
    TempDir dir;
    rgnav::LineReader lines(rgnav::testing::sharedData("laser/corrected/intel-corrected.log.gz"));
    std::string text;
    std::size_t garbled = 0, flasers = 0;
    for (int i = 0; i < 3000; ++i) {
      const std::string line(lines.next().value().text);
      const bool garble = startsWith(line, "FLASER ") && flasers++ % 2 == 0;
      garbled += garble ? 1 : 0;
      text += (garble ? line.substr(0, line.size() / 2) : line) + "\n";
    }
    const std::string gz = rgnav::testing::gzipCompress(text);
    const std::string path = dir.file("intel-start.log.gz");
    rgnav::testing::writeFile(path, gz.substr(0, gz.size() * 2 / 3));
    CarmenLogReader reader(path);
    const auto readToEnd = [&reader] {
      while (reader.next()) {
      }
    };
    CPPUNIT_ASSERT_THROW(readToEnd(), rgnav::FormatError);
    const rgnav::LogStats& stats = reader.stats();
    CPPUNIT_ASSERT(garbled > 50);
    CPPUNIT_ASSERT(stats.malformedLines > garbled / 2 && stats.malformedLines <= garbled);
    CPPUNIT_ASSERT(stats.truncated);
    CPPUNIT_ASSERT(startsWith(stats.truncation, path + ":"));
    const std::vector<std::string> described = rgnav::describeSkips(stats);
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, described.size());
    CPPUNIT_ASSERT(startsWith(described[0], std::to_string(stats.malformedLines) + " malformed lines skipped, the first " +
                                                path + ":"));
    CPPUNIT_ASSERT_EQUAL("skipped_lines=" + std::to_string(stats.malformedLines) + " truncated=yes",
                         rgnav::skipFigures(stats));
  }

  void missingFileAndDirectoryFailAtOpen() {
    TempDir dir;
    for (const std::string& path : {dir.file("missing.log.gz"), dir.path()}) {
      CPPUNIT_ASSERT_THROW(CarmenLogReader{path}, rgnav::FileError);
      try {
        rgnav::openLog(path);
        CPPUNIT_FAIL("no FileError for " + path);
      } catch (const rgnav::FileError& e) {
        CPPUNIT_ASSERT(std::string(e.what()).find(path) != std::string::npos);
      }
    }
  }

  void badOptionsAreRejected() {
    TempDir dir;
    rgnav::testing::writeFile(dir.file("ok.log"), kOdom);
    for (const double maxRange : {0.0, -1.0, std::nan("")}) {
      rgnav::LogReaderOptions options;
      options.maxRange = maxRange;
      CPPUNIT_ASSERT_THROW(CarmenLogReader(dir.file("ok.log"), options),
                           rgnav::InvalidArgumentError);
    }
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(CarmenBadInputTest);
