// Tests withIdlErrors: each typed error becomes the IDL exception the operation declares, an
// error the operation does not declare and every other exception become Failed with the message,
// and IDL exceptions thrown by the work pass unchanged.
#include <cppunit/extensions/HelperMacros.h>

#include <stdexcept>
#include <string>

#include "servers/common/IdlErrors.h"

using namespace rgnav;

namespace {

template <class Idl, class F>
Idl caught(Raises declared, F&& work) {
  try {
    withIdlErrors(declared, std::forward<F>(work));
  } catch (const Idl& e) {
    return e;
  } catch (const CORBA::Exception& e) {
    CPPUNIT_FAIL(std::string("unexpected ") + e._name());
  }
  CPPUNIT_FAIL("nothing thrown");
  return Idl();
}

}  // namespace

class IdlErrorsTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(IdlErrorsTest);
  CPPUNIT_TEST(declaredErrorsKeepTheirKind);
  CPPUNIT_TEST(undeclaredErrorsAreFailed);
  CPPUNIT_TEST(everyOtherExceptionIsFailed);
  CPPUNIT_TEST(idlExceptionsPass);
  CPPUNIT_TEST(resultsPass);
  CPPUNIT_TEST_SUITE_END();

 public:
  void declaredErrorsKeepTheirKind() {
    const Raises all = Raises::InvalidArgument | Raises::NotAvailable | Raises::NotSupported;
    const auto bad = caught<RGNav::InvalidArgument>(all, [] { throw InvalidArgumentError("bad id"); });
    CPPUNIT_ASSERT_EQUAL(std::string("bad id"), std::string(bad.message.in()));
    const auto gone = caught<RGNav::NotAvailable>(all, [] { throw NotAvailableError("gone"); });
    CPPUNIT_ASSERT_EQUAL(std::string("gone"), std::string(gone.message.in()));
    caught<RGNav::NotSupported>(all, [] { throw NotSupportedError("cannot"); });
  }

  void undeclaredErrorsAreFailed() {
    const auto failed = caught<RGNav::Failed>(Raises::NotAvailable, [] { throw InvalidArgumentError("no region 7"); });
    CPPUNIT_ASSERT_EQUAL(std::string("no region 7"), std::string(failed.message.in()));
    caught<RGNav::Failed>(Raises::FailedOnly, [] { throw NotAvailableError("x"); });
    caught<RGNav::Failed>(Raises::InvalidArgument, [] { throw NotSupportedError("x"); });
  }

  void everyOtherExceptionIsFailed() {
    const auto file = caught<RGNav::Failed>(Raises::InvalidArgument, [] { throw FileError("map.json: disk full"); });
    CPPUNIT_ASSERT_EQUAL(std::string("map.json: disk full"), std::string(file.message.in()));
    const auto range = caught<RGNav::Failed>(Raises::InvalidArgument, [] { throw std::out_of_range("vector::at"); });
    CPPUNIT_ASSERT_EQUAL(std::string("vector::at"), std::string(range.message.in()));
    caught<RGNav::Failed>(Raises::FailedOnly, [] { throw 42; });
  }

  void idlExceptionsPass() {
    const auto bad = caught<RGNav::InvalidArgument>(Raises::InvalidArgument,
                                                    [] { throw RGNav::InvalidArgument("maxCount", "must be at least 1"); });
    CPPUNIT_ASSERT_EQUAL(std::string("maxCount"), std::string(bad.field.in()));
  }

  void resultsPass() { CPPUNIT_ASSERT_EQUAL(7, withIdlErrors(Raises::FailedOnly, [] { return 7; })); }
};

CPPUNIT_TEST_SUITE_REGISTRATION(IdlErrorsTest);
