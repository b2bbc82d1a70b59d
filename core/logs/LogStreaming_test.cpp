// Tests that a large log is read as a stream: 200 000 generated lines (about 130 MB decoded,
// gzip-compressed on the fly) are read with far less memory than the decoded size.
#include <cppunit/extensions/HelperMacros.h>
#include <sys/resource.h>
#include <zlib.h>

#include <string>

#include "core/logs/CarmenLogReader.h"
#include "core/logs/LogTestFiles.h"

using rgnav::testing::TempDir;

namespace {

constexpr std::size_t kLines = 200000;

// Peak resident memory of this process so far, in bytes.
std::size_t peakMemory() {
  struct rusage usage {};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<std::size_t>(usage.ru_maxrss) * 1024;
}

// Writes kLines lines, every fourth a 360-beam FLASER, the others ODOM; returns the decoded size.
std::size_t writeLargeLog(const std::string& path) {
  gzFile out = gzopen(path.c_str(), "wb1");
  CPPUNIT_ASSERT(out != nullptr);
  std::size_t decoded = 0;
  for (std::size_t i = 0; i < kLines; ++i) {
    const std::string stamp = std::to_string(i * 0.01);
    std::string line;
    if (i % 4 == 0) {
      line = "FLASER 360";
      for (std::size_t b = 0; b < 360; ++b) {
        line += ' ';
        line += std::to_string(1.0 + static_cast<double>((b * 7 + i) % 5000) / 1000.0);
      }
      line += " 1 2 0.5 1 2 0.5 " + stamp + " host " + stamp + "\n";
    } else {
      line = "ODOM 1.5 2.5 0.25 0.1 0.01 0 " + stamp + " host " + stamp + "\n";
    }
    CPPUNIT_ASSERT(gzwrite(out, line.data(), static_cast<unsigned>(line.size())) > 0);
    decoded += line.size();
  }
  CPPUNIT_ASSERT_EQUAL(Z_OK, gzclose(out));
  return decoded;
}

}  // namespace

class LogStreamingTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(LogStreamingTest);
  CPPUNIT_TEST(largeLogIsReadAsAStream);
  CPPUNIT_TEST_SUITE_END();

 public:
  void largeLogIsReadAsAStream() {
    TempDir dir;
    const std::string path = dir.file("large.log.gz");
    const std::size_t decoded = writeLargeLog(path);
    CPPUNIT_ASSERT(decoded > 100u << 20);

    const std::size_t before = peakMemory();
    rgnav::CarmenLogReader reader(path);
    rgnav::DataId lastScan = 0;
    rgnav::DataId lastOdometry = 0;
    while (auto record = reader.next()) {
      if (const auto* scan = std::get_if<rgnav::LaserScan>(&*record)) {
        CPPUNIT_ASSERT_EQUAL(lastScan + 1, scan->id);
        CPPUNIT_ASSERT_EQUAL(std::size_t{360}, scan->ranges.size());
        lastScan = scan->id;
      } else {
        lastOdometry = std::get<rgnav::OdometryReading>(*record).id;
      }
    }
    CPPUNIT_ASSERT_EQUAL(rgnav::DataId{kLines / 4}, lastScan);
    CPPUNIT_ASSERT_EQUAL(rgnav::DataId{kLines - kLines / 4}, lastOdometry);
    CPPUNIT_ASSERT_EQUAL(kLines, reader.stats().lines);
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, reader.stats().malformedLines);
    CPPUNIT_ASSERT(peakMemory() - before < decoded / 4);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(LogStreamingTest);
