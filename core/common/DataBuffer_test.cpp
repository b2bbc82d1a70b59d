// Tests the bounded ID buffer: ranges after an ID, eviction, out-of-range IDs, bad counts.
#include <cppunit/extensions/HelperMacros.h>

#include "core/common/DataBuffer.h"

using rgnav::DataBuffer;
using rgnav::OdometryReading;

namespace {
DataBuffer<OdometryReading> filled(std::size_t capacity, rgnav::DataId count) {
  DataBuffer<OdometryReading> buffer(capacity);
  for (rgnav::DataId id = 1; id <= count; ++id) buffer.push(OdometryReading{id, double(id), {}, 0, 0});
  return buffer;
}
}  // namespace

class DataBufferTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(DataBufferTest);
  CPPUNIT_TEST(sinceReturnsConsecutiveRecordsAfterId);
  CPPUNIT_TEST(evictsOldestWhenFull);
  CPPUNIT_TEST(outOfRangeIdsAreTypedErrors);
  CPPUNIT_TEST(rejectsNonConsecutiveIds);
  CPPUNIT_TEST_SUITE_END();

 public:
  void sinceReturnsConsecutiveRecordsAfterId() {
    const auto buffer = filled(100, 10);
    const auto batch = buffer.since(3, 4);
    CPPUNIT_ASSERT_EQUAL(std::size_t(4), batch.records.size());
    CPPUNIT_ASSERT_EQUAL(rgnav::DataId(4), batch.records.front().id);
    CPPUNIT_ASSERT_EQUAL(rgnav::DataId(7), batch.records.back().id);
    CPPUNIT_ASSERT_EQUAL(rgnav::DataId(10), batch.latestId);
    CPPUNIT_ASSERT(buffer.since(10, 5).records.empty());
    CPPUNIT_ASSERT(buffer.since(1000, 5).records.empty());
    CPPUNIT_ASSERT_EQUAL(std::size_t(10), buffer.since(0, 50).records.size());
  }
  void evictsOldestWhenFull() {
    const auto buffer = filled(5, 12);
    CPPUNIT_ASSERT_EQUAL(rgnav::DataId(8), buffer.oldestId());
    const auto batch = buffer.since(2, 100);
    CPPUNIT_ASSERT_EQUAL(rgnav::DataId(8), batch.records.front().id);
    CPPUNIT_ASSERT_EQUAL(std::size_t(5), batch.records.size());
  }
  void outOfRangeIdsAreTypedErrors() {
    const auto buffer = filled(5, 12);
    CPPUNIT_ASSERT_THROW(buffer.get(0), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(buffer.get(7), rgnav::NotAvailableError);
    CPPUNIT_ASSERT_THROW(buffer.get(13), rgnav::NotAvailableError);
    CPPUNIT_ASSERT_THROW(buffer.get(UINT64_MAX), rgnav::NotAvailableError);
    CPPUNIT_ASSERT_EQUAL(rgnav::DataId(9), buffer.get(9).id);
    CPPUNIT_ASSERT_THROW(buffer.since(0, 0), rgnav::InvalidArgumentError);
  }
  void rejectsNonConsecutiveIds() {
    auto buffer = filled(5, 3);
    CPPUNIT_ASSERT_THROW(buffer.push(OdometryReading{5, 0, {}, 0, 0}), rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(DataBufferTest);
