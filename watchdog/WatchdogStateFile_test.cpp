// Tests the watchdog state file: round trip, missing file, atomic replacement (no partial or
// temporary file left, a failed write keeps the old file) and rejection of malformed files.
#include <cppunit/extensions/HelperMacros.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "core/common/Errors.h"
#include "watchdog/WatchdogStateFile.h"
#include "watchdog/testing/TempDir.h"
#include "watchdog/testing/Wait.h"

using rgnav::ProcessRecord;
using rgnav::WatchdogStateFile;
using Records = std::vector<ProcessRecord>;

class WatchdogStateFileTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(WatchdogStateFileTest);
  CPPUNIT_TEST(roundTrip);
  CPPUNIT_TEST(missingFileMeansNoProcesses);
  CPPUNIT_TEST(writeReplacesWholeFileAndLeavesNoTemporary);
  CPPUNIT_TEST(staleTemporaryFileDoesNotStopWrites);
  CPPUNIT_TEST(rejectsMalformedFiles);
  CPPUNIT_TEST(rejectsBadModuleName);
  CPPUNIT_TEST_SUITE_END();

  rgnav::testing::TempDir dir_;
  const Records three_{{"LogPlayback", 4242, 987654321012ULL}, {"ScanMapper", 4243, 987654321013ULL},
                       {"Kernel", 99999, 1}};

  void writeText(const std::string& text) { std::ofstream(dir_.file("state")) << text; }

 public:
  void roundTrip() {
    const WatchdogStateFile file(dir_.file("state"));
    file.write(three_);
    CPPUNIT_ASSERT(three_ == file.read());
    file.write({});
    CPPUNIT_ASSERT(file.read().empty());
  }
  void missingFileMeansNoProcesses() { CPPUNIT_ASSERT(WatchdogStateFile(dir_.file("none")).read().empty()); }
  void writeReplacesWholeFileAndLeavesNoTemporary() {
    const WatchdogStateFile file(dir_.file("state"));
    file.write(three_);
    file.write({three_[1]});
    CPPUNIT_ASSERT_EQUAL(std::string("rgnav-watchdog-state 1\nScanMapper 4243 987654321013\n"),
                         rgnav::testing::readFile(file.path()));
    CPPUNIT_ASSERT(!std::filesystem::exists(file.path() + ".tmp"));
  }
  void staleTemporaryFileDoesNotStopWrites() {
    const WatchdogStateFile file(dir_.file("state"));
    file.write(three_);
    // What a watchdog that crashed while writing may have left (AtomicFile_test: failures).
    std::filesystem::create_directory(file.path() + ".tmp");
    file.write({three_[0]});
    CPPUNIT_ASSERT(std::vector<rgnav::ProcessRecord>{three_[0]} == file.read());
  }
  void rejectsMalformedFiles() {
    const WatchdogStateFile file(dir_.file("state"));
    writeText("LogPlayback 4242 1\n");
    CPPUNIT_ASSERT_THROW(file.read(), rgnav::FormatError);
    for (const std::string bad : {"LogPlayback 4242\n", "LogPlayback 4242 1 extra\n", "LogPlayback x 1\n",
                                  "LogPlayback 1 5\n"}) {
      writeText("rgnav-watchdog-state 1\nKernel 77 5\n" + bad);
      try {
        file.read();
        CPPUNIT_FAIL("expected FormatError for " + bad);
      } catch (const rgnav::FormatError& e) {
        CPPUNIT_ASSERT_EQUAL(std::size_t(3), e.line());
      }
    }
  }
  void rejectsBadModuleName() {
    const WatchdogStateFile file(dir_.file("state"));
    CPPUNIT_ASSERT_THROW(file.write({{"Log Playback", 42, 1}}), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(file.write({{"", 42, 1}}), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT(!std::filesystem::exists(file.path()));
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(WatchdogStateFileTest);
