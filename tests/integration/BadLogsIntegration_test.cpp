// integration_bad_logs_test: the playback server under the real watchdog on logs it cannot use.
// A missing file or a directory is a crash at start: after max_restarts the module is FATAL
// and its log names the problem. Binary garbage, a truncated .gz and a log with garbled lines
// are served as far as they can be read, with the problem in the module's status (skipped lines
// and truncation counted), a summary with the first file:line of each kind in its log, and the
// server never crashes (the watchdog counts no restart).
#include <cppunit/extensions/HelperMacros.h>

#include <fstream>
#include <random>
#include <variant>

#include "core/logs/LineReader.h"
#include "core/logs/OpenLog.h"
#include "tests/integration/IntegrationHelpers.h"

using namespace rgnav;
using namespace rgnav::testing;

namespace {

void writeFile(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

std::size_t scansIn(const std::string& log) {
  auto source = openLog(log);
  std::size_t scans = 0;
  while (auto record = source->next()) scans += std::holds_alternative<LaserScan>(*record);
  return scans;
}

// One playback module "BadLog" on `log`; FATAL after two restarts.
ClusterModule badLogModule(const std::string& log) {
  return {"BadLog", playbackCommand(log), {"Laser", "Base"}, {}, "max_restarts: 2"};
}

}  // namespace

class BadLogsIntegrationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(BadLogsIntegrationTest);
  CPPUNIT_TEST(testMissingFileIsFatalWithReason);
  CPPUNIT_TEST(testDirectoryIsFatalWithReason);
  CPPUNIT_TEST(testBinaryGarbageIsServedAsNoData);
  CPPUNIT_TEST(testTruncatedGzipServesTheReadablePart);
  CPPUNIT_TEST(testGarbledLinesAreSkippedAndCounted);
  CPPUNIT_TEST_SUITE_END();

 public:
  void testMissingFileIsFatalWithReason() {
    const ScratchDir scratch("rgnav-badlogs");
    expectFatalAtStart(scratch.file("no-such.log"), "No such file or directory");
  }

  void testDirectoryIsFatalWithReason() {
    const ScratchDir scratch("rgnav-badlogs");
    expectFatalAtStart(scratch.path.string(), "is a directory");
  }

  void testBinaryGarbageIsServedAsNoData() {
    const ScratchDir scratch("rgnav-badlogs");
    std::mt19937 random(7);
    std::string bytes(64 * 1024, '\0');
    for (char& c : bytes) c = static_cast<char>(random() & 0xff);
    bytes[0] = '@';  // not a gzip or xz magic number: the file is read as (bad) text
    writeFile(scratch.file("garbage.log"), bytes);

    TestCluster cluster({badLogModule(scratch.file("garbage.log"))}, kFastBackoff);
    cluster.start();
    LaserClient laser(cluster.clientSettings());
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, readAllScans(laser).size());
    const ModuleStatusInfo status = laser.status();
    CPPUNIT_ASSERT(status.counters.at("log_malformed_lines") > 0);
    CPPUNIT_ASSERT(!status.lastError.empty());
    expectNeverRestarted(cluster);
  }

  void testTruncatedGzipServesTheReadablePart() {
    const ScratchDir scratch("rgnav-badlogs");
    const std::string whole = readFile(intelLog());
    writeFile(scratch.file("truncated.log.gz"), whole.substr(0, whole.size() / 2));

    TestCluster cluster({badLogModule(scratch.file("truncated.log.gz"))}, kFastBackoff);
    cluster.start();
    LaserClient laser(cluster.clientSettings());
    const std::vector<LaserScan> scans = readAllScans(laser);
    CPPUNIT_ASSERT(scans.size() > 100);
    CPPUNIT_ASSERT(scans.size() < kIntelScans);
    CPPUNIT_ASSERT_EQUAL(DataId(scans.size()), scans.back().id);
    const ModuleStatusInfo status = laser.status();
    CPPUNIT_ASSERT_MESSAGE("lastError: " + status.lastError,
                           status.lastError.find("truncated.log.gz") != std::string::npos);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{1}, status.counters.at("log_truncated"));
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{0}, status.counters.at("log_skipped_lines"));
    expectInModuleLog(cluster, "skipped_lines=0 truncated=yes");
    expectInModuleLog(cluster, "playback: the log ends early, the rest is lost: " + scratch.file("truncated.log.gz") + ":");
    expectNeverRestarted(cluster);
  }

  void testGarbledLinesAreSkippedAndCounted() {
    const ScratchDir scratch("rgnav-badlogs");
    const std::vector<std::string> garbage = {"FLASER abc", "ODOM 1 2", "@@@ not a log line", "FLASER 3 1.0 2.0",
                                              "\x01\x02\x03\xff\xfe"};
    std::string clean, garbled;
    std::size_t inserted = 0;
    LineReader lines(intelLog());
    for (std::size_t n = 0; n < 3000; ++n) {
      const auto line = lines.next();
      CPPUNIT_ASSERT(line);
      clean += std::string(line->text) + "\n";
      garbled += std::string(line->text) + "\n";
      if (n % 25 == 24) garbled += garbage[inserted++ % garbage.size()] + "\n";
    }
    writeFile(scratch.file("clean.log"), clean);
    writeFile(scratch.file("garbled.log"), garbled);
    const std::size_t goodScans = scansIn(scratch.file("clean.log"));
    CPPUNIT_ASSERT(goodScans > 50);

    TestCluster cluster({badLogModule(scratch.file("garbled.log"))}, kFastBackoff);
    cluster.start();
    LaserClient laser(cluster.clientSettings());
    const std::vector<LaserScan> scans = readAllScans(laser);
    CPPUNIT_ASSERT_EQUAL(goodScans, scans.size());
    for (std::size_t i = 0; i < scans.size(); ++i) CPPUNIT_ASSERT_EQUAL(DataId(i + 1), scans[i].id);
    const ModuleStatusInfo status = laser.status();
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{inserted}, status.counters.at("log_malformed_lines"));
    CPPUNIT_ASSERT_MESSAGE("lastError: " + status.lastError,
                           status.lastError.find("garbled.log:") != std::string::npos);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{inserted}, status.counters.at("log_skipped_lines"));
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{0}, status.counters.at("log_truncated"));
    expectInModuleLog(cluster, "skipped_lines=" + std::to_string(inserted) + " truncated=no");
    expectInModuleLog(cluster, "playback: " + std::to_string(inserted) + " malformed lines skipped, the first " +
                                   scratch.file("garbled.log") + ":26: FLASER");
    expectNeverRestarted(cluster);
  }

 private:
  static void expectInModuleLog(TestCluster& cluster, const std::string& text) {
    const std::string moduleLog = readFile(cluster.dir() + "/run/logs/BadLog.log");
    CPPUNIT_ASSERT_MESSAGE("module log: " + moduleLog + "\nlacks: " + text, moduleLog.find(text) != std::string::npos);
  }

  // The module crashes at every start: FATAL after max_restarts, with `reason` in its log.
  static void expectFatalAtStart(const std::string& log, const std::string& reason) {
    TestCluster cluster({badLogModule(log)}, kFastBackoff);
    cluster.start({"NameService"});
    const ModuleProcessInfo info = cluster.waitFor("BadLog", inState(ProcessState::Fatal), "FATAL");
    CPPUNIT_ASSERT_EQUAL(std::uint32_t{2}, info.restarts);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, eventsOf(cluster.watchdog(), "BadLog", "FATAL").size());
    const std::string moduleLog = readFile(cluster.dir() + "/run/logs/BadLog.log");
    CPPUNIT_ASSERT_MESSAGE("module log: " + moduleLog, moduleLog.find(reason) != std::string::npos);
    CPPUNIT_ASSERT_MESSAGE("module log: " + moduleLog, moduleLog.find(log) != std::string::npos);
    CPPUNIT_ASSERT(isRunning(cluster.describe("NameService")));
  }

  static void expectNeverRestarted(TestCluster& cluster) {
    const ModuleProcessInfo info = cluster.describe("BadLog");
    CPPUNIT_ASSERT(isRunning(info));
    CPPUNIT_ASSERT_EQUAL(std::uint32_t{0}, info.restarts);
    CPPUNIT_ASSERT(eventsOf(cluster.watchdog(), "BadLog", "exited").empty());
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(BadLogsIntegrationTest);
