// Tests the event log: one timestamped line per event, increasing IDs, the bounded memory with
// "since ID" queries, IDs continuing across restarts, and concurrent writers.
#include <cppunit/extensions/HelperMacros.h>

#include <regex>
#include <set>
#include <sstream>
#include <thread>

#include "core/common/Errors.h"
#include "watchdog/EventLog.h"
#include "watchdog/testing/TempDir.h"
#include "watchdog/testing/Wait.h"

using rgnav::EventLog;
using rgnav::EventsSince;

namespace {

std::vector<std::string> lines(const std::string& path) {
  std::istringstream text(rgnav::testing::readFile(path));
  std::vector<std::string> out;
  for (std::string line; std::getline(text, line);) out.push_back(line);
  return out;
}

std::vector<std::uint64_t> ids(const EventsSince& since) {
  std::vector<std::uint64_t> out;
  for (const rgnav::Event& e : since.events) out.push_back(e.id);
  return out;
}

}  // namespace

class EventLogTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(EventLogTest);
  CPPUNIT_TEST(appendsOneTimestampedLinePerEvent);
  CPPUNIT_TEST(keepsLastEventsForSinceQueries);
  CPPUNIT_TEST(continuesIdsAfterRestart);
  CPPUNIT_TEST(concurrentWritersGetUniqueOrderedIds);
  CPPUNIT_TEST(rejectsBadArguments);
  CPPUNIT_TEST_SUITE_END();

  rgnav::testing::TempDir dir_;

 public:
  void appendsOneTimestampedLinePerEvent() {
    EventLog log(dir_.file("events.log"), 10);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(0), log.lastId());
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(1), log.record("LogPlayback", "started", "pid 4242"));
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(2), log.record("Scan Mapper", "exited", "code 3\nsecond line"));
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(3), log.record("", "shutdown", ""));
    const std::vector<std::string> written = lines(dir_.file("events.log"));
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), written.size());
    const std::string stamp = R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z )";
    CPPUNIT_ASSERT_MESSAGE(written[0], std::regex_match(written[0], std::regex(stamp + "1 LogPlayback started pid 4242")));
    CPPUNIT_ASSERT_MESSAGE(written[1], std::regex_match(written[1], std::regex(stamp + "2 Scan_Mapper exited code 3 second line")));
    CPPUNIT_ASSERT_MESSAGE(written[2], std::regex_match(written[2], std::regex(stamp + "3 - shutdown ")));
    const EventsSince all = log.since(0);
    CPPUNIT_ASSERT_EQUAL(std::string("Scan_Mapper"), all.events[1].module);
    CPPUNIT_ASSERT(all.events[0].time <= all.events[2].time);
  }
  void keepsLastEventsForSinceQueries() {
    EventLog log(dir_.file("events.log"), 3);
    for (int i = 0; i < 5; ++i) log.record("M", "tick", std::to_string(i));
    const EventsSince fromStart = log.since(0);
    CPPUNIT_ASSERT(ids(fromStart) == std::vector<std::uint64_t>({3, 4, 5}));
    CPPUNIT_ASSERT(fromStart.missed);  // 1 and 2 are gone
    const EventsSince fromTwo = log.since(2);
    CPPUNIT_ASSERT(ids(fromTwo) == std::vector<std::uint64_t>({3, 4, 5}));
    CPPUNIT_ASSERT(!fromTwo.missed);
    CPPUNIT_ASSERT(ids(log.since(4)) == std::vector<std::uint64_t>({5}));
    const EventsSince none = log.since(5);
    CPPUNIT_ASSERT(none.events.empty() && !none.missed);
    CPPUNIT_ASSERT_EQUAL(std::size_t(5), lines(dir_.file("events.log")).size());  // the file keeps all
  }
  void continuesIdsAfterRestart() {
    {
      EventLog first(dir_.file("events.log"), 10);
      for (int i = 0; i < 4; ++i) first.record("M", "tick", "pid 99999999");
    }
    EventLog second(dir_.file("events.log"), 10);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(4), second.lastId());
    const EventsSince before = second.since(2);
    CPPUNIT_ASSERT(before.events.empty() && before.missed);  // events 3, 4 are only in the file
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(5), second.record("M", "tick", ""));
  }
  void concurrentWritersGetUniqueOrderedIds() {
    const int threads = 4;
    const int each = 250;
    {
      EventLog log(dir_.file("events.log"), threads * each);
      std::vector<std::thread> writers;
      for (int t = 0; t < threads; ++t) {
        writers.emplace_back([&log, t] {
          for (int i = 0; i < each; ++i) log.record("Writer", "tick", std::to_string(t) + ":" + std::to_string(i));
        });
      }
      for (std::thread& w : writers) w.join();
      CPPUNIT_ASSERT_EQUAL(std::uint64_t(threads * each), log.lastId());
      CPPUNIT_ASSERT_EQUAL(std::size_t(threads * each), log.since(0).events.size());
    }
    const std::vector<std::string> written = lines(dir_.file("events.log"));
    CPPUNIT_ASSERT_EQUAL(std::size_t(threads * each), written.size());
    for (std::size_t i = 0; i < written.size(); ++i) {
      std::istringstream fields(written[i]);
      std::string stamp;
      std::uint64_t id = 0;
      fields >> stamp >> id;
      CPPUNIT_ASSERT_EQUAL(std::uint64_t(i + 1), id);
    }
  }
  void rejectsBadArguments() {
    CPPUNIT_ASSERT_THROW(EventLog(dir_.file("events.log"), 0), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(EventLog(dir_.file("missing/events.log"), 10), rgnav::FileError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(EventLogTest);
