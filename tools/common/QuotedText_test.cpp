// Tests quotedText: plain names are only quoted; newlines, quotes and other control characters
// are escaped, so the quoted text is one line that ends where its closing quote is.
#include <cppunit/extensions/HelperMacros.h>

#include "tools/common/QuotedText.h"

using rgnav::quotedText;

class QuotedTextTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(QuotedTextTest);
  CPPUNIT_TEST(plainNamesAreQuoted);
  CPPUNIT_TEST(controlCharactersCannotStartALine);
  CPPUNIT_TEST_SUITE_END();

 public:
  void plainNamesAreQuoted() {
    CPPUNIT_ASSERT_EQUAL(std::string("\"lab 2\""), quotedText("lab 2"));
    CPPUNIT_ASSERT_EQUAL(std::string("\"\""), quotedText(""));
    CPPUNIT_ASSERT_EQUAL(std::string("\"K\xc3\xbc" "che\""), quotedText("K\xc3\xbc" "che"));  // UTF-8 stays
  }

  void controlCharactersCannotStartALine() {
    const std::string forged = quotedText("lab\nregion 9 \"x\\\" frame=0,0,0\r\x1b[2J\x7f\t");
    CPPUNIT_ASSERT_EQUAL(std::string("\"lab\\nregion 9 \\\"x\\\\\\\" frame=0,0,0\\x0d\\x1b[2J\\x7f\\t\""), forged);
    for (const char c : forged) CPPUNIT_ASSERT(static_cast<unsigned char>(c) >= 0x20 && c != 0x7f);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(QuotedTextTest);
