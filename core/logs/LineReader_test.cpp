// Tests LineReader: plain/gzip/xz detection by magic bytes, line numbering, over-long lines,
// truncated and corrupt compressed data, and files that cannot be opened.
#include <cppunit/extensions/HelperMacros.h>

#include <random>
#include <string>
#include <vector>

#include "core/common/Errors.h"
#include "core/logs/LineReader.h"
#include "core/logs/LogTestFiles.h"

using rgnav::LineReader;
using rgnav::testing::TempDir;

namespace {

std::vector<std::string> readLines(LineReader& reader) {
  std::vector<std::string> lines;
  while (const auto line = reader.next()) {
    CPPUNIT_ASSERT_EQUAL(lines.size() + 1, line->number);
    lines.push_back(line->overLong ? "<over-long>" : std::string(line->text));
  }
  return lines;
}

std::vector<std::string> readLines(const std::string& path, std::size_t cap) {
  LineReader reader(path, cap);
  return readLines(reader);
}

// Lines of varied numbers, so that compressed data is not trivially small.
std::string numberedLines(std::size_t count) {
  std::mt19937 random(7);
  std::string text;
  for (std::size_t i = 1; i <= count; ++i) {
    text += "ODOM " + std::to_string(i) + " " + std::to_string(random() % 100000) + " " +
            std::to_string(random()) + "\n";
  }
  return text;
}

// Reads `path` until it throws; checks the error names the line after the last good one.
std::size_t linesBeforeFormatError(const std::string& path) {
  LineReader reader(path);
  std::size_t good = 0;
  try {
    while (reader.next()) {
      ++good;
    }
  } catch (const rgnav::FormatError& e) {
    CPPUNIT_ASSERT_EQUAL(path, e.file());
    CPPUNIT_ASSERT_EQUAL(good + 1, e.line());
    return good;
  }
  CPPUNIT_FAIL("no FormatError for " + path);
  return 0;
}

}  // namespace

class LineReaderTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(LineReaderTest);
  CPPUNIT_TEST(compressionIsDetectedByMagicNotByName);
  CPPUNIT_TEST(emptyFilesHaveNoLines);
  CPPUNIT_TEST(concatenatedGzipMembersAreRead);
  CPPUNIT_TEST(lineSpanningChunksIsKept);
  CPPUNIT_TEST(overLongLinesAreSkippedAndFlagged);
  CPPUNIT_TEST(tenMegabyteLineIsSkipped);
  CPPUNIT_TEST(truncatedGzipNamesTheLineReached);
  CPPUNIT_TEST(truncatedXzNamesTheLineReached);
  CPPUNIT_TEST(corruptGzipIsFormatError);
  CPPUNIT_TEST(garbageAfterCompressionMagicIsFormatError);
  CPPUNIT_TEST(missingFileAndDirectoryAreFileErrors);
  CPPUNIT_TEST(zeroCapIsRejected);
  CPPUNIT_TEST_SUITE_END();

 public:
  void compressionIsDetectedByMagicNotByName() {
    TempDir dir;
    const std::string text = "a\nbb\r\n\nlast";
    const std::vector<std::string> expected = {"a", "bb", "", "last"};
    rgnav::testing::writeFile(dir.file("plain.gz"), text);
    rgnav::testing::writeFile(dir.file("gzip.txt"), rgnav::testing::gzipCompress(text));
    rgnav::testing::writeFile(dir.file("xz.log"), rgnav::testing::xzCompress(text));
    for (const char* name : {"plain.gz", "gzip.txt", "xz.log"}) {
      CPPUNIT_ASSERT(expected == readLines(dir.file(name), 100));
    }
  }

  void emptyFilesHaveNoLines() {
    TempDir dir;
    rgnav::testing::writeFile(dir.file("empty"), "");
    rgnav::testing::writeFile(dir.file("empty.gz"), rgnav::testing::gzipCompress(""));
    rgnav::testing::writeFile(dir.file("empty.xz"), rgnav::testing::xzCompress(""));
    for (const char* name : {"empty", "empty.gz", "empty.xz"}) {
      CPPUNIT_ASSERT(readLines(dir.file(name), 100).empty());
    }
  }

  void concatenatedGzipMembersAreRead() {
    TempDir dir;
    rgnav::testing::writeFile(dir.file("two.gz"), rgnav::testing::gzipCompress("one\ntw") +
                                                      rgnav::testing::gzipCompress("o\nthree\n"));
    CPPUNIT_ASSERT(std::vector<std::string>({"one", "two", "three"}) ==
                   readLines(dir.file("two.gz"), 100));
  }

  void lineSpanningChunksIsKept() {
    TempDir dir;
    const std::string longLine(300000, 'x');
    rgnav::testing::writeFile(dir.file("long.xz"),
                              rgnav::testing::xzCompress("a\n" + longLine + "\nb\n"));
    const auto lines = readLines(dir.file("long.xz"), LineReader::kDefaultMaxLineLength);
    CPPUNIT_ASSERT(std::vector<std::string>({"a", longLine, "b"}) == lines);
  }

  void overLongLinesAreSkippedAndFlagged() {
    TempDir dir;
    rgnav::testing::writeFile(dir.file("cap"), "12345\n123456\nok\n1234567");
    CPPUNIT_ASSERT(std::vector<std::string>({"12345", "<over-long>", "ok", "<over-long>"}) ==
                   readLines(dir.file("cap"), 5));
  }

  void tenMegabyteLineIsSkipped() {
    TempDir dir;
    const std::string huge(10 << 20, 'y');
    rgnav::testing::writeFile(dir.file("huge"), "before\n" + huge + "\nafter\n" + huge);
    rgnav::testing::writeFile(dir.file("huge.gz"),
                              rgnav::testing::gzipCompress("before\n" + huge + "\nafter\n"));
    CPPUNIT_ASSERT(std::vector<std::string>({"before", "<over-long>", "after", "<over-long>"}) ==
                   readLines(dir.file("huge"), LineReader::kDefaultMaxLineLength));
    CPPUNIT_ASSERT(std::vector<std::string>({"before", "<over-long>", "after"}) ==
                   readLines(dir.file("huge.gz"), LineReader::kDefaultMaxLineLength));
  }

  void truncatedGzipNamesTheLineReached() {
    TempDir dir;
    const std::string gz = rgnav::testing::gzipCompress(numberedLines(50000));
    rgnav::testing::writeFile(dir.file("cut.gz"), gz.substr(0, gz.size() / 2));
    const std::size_t good = linesBeforeFormatError(dir.file("cut.gz"));
    CPPUNIT_ASSERT(good > 1000 && good < 50000);
  }

  void truncatedXzNamesTheLineReached() {
    TempDir dir;
    const std::string xz = rgnav::testing::xzCompress(numberedLines(50000));
    rgnav::testing::writeFile(dir.file("cut.xz"), xz.substr(0, xz.size() / 2));
    const std::size_t good = linesBeforeFormatError(dir.file("cut.xz"));
    CPPUNIT_ASSERT(good > 1000 && good < 50000);
    rgnav::testing::writeFile(dir.file("header-only.xz"), xz.substr(0, 8));
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, linesBeforeFormatError(dir.file("header-only.xz")));
  }

  void corruptGzipIsFormatError() {
    TempDir dir;
    std::string gz = rgnav::testing::gzipCompress(numberedLines(20000));
    for (std::size_t i = gz.size() / 2; i < gz.size() / 2 + 64; ++i) {
      gz[i] = static_cast<char>(~gz[i]);
    }
    rgnav::testing::writeFile(dir.file("bad.gz"), gz);
    linesBeforeFormatError(dir.file("bad.gz"));
  }

  void garbageAfterCompressionMagicIsFormatError() {
    TempDir dir;
    const std::string gzipMagic = "\x1f\x8b";
    const std::string xzMagic("\xfd" "7zXZ\0", 6);
    rgnav::testing::writeFile(dir.file("g.gz"), gzipMagic + rgnav::testing::randomBytes(100000, 1));
    rgnav::testing::writeFile(dir.file("g.xz"), xzMagic + rgnav::testing::randomBytes(100000, 2));
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, linesBeforeFormatError(dir.file("g.gz")));
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, linesBeforeFormatError(dir.file("g.xz")));
  }

  void missingFileAndDirectoryAreFileErrors() {
    TempDir dir;
    for (const std::string& path : {dir.file("missing.log"), dir.path()}) {
      try {
        LineReader reader(path);
        CPPUNIT_FAIL("no FileError for " + path);
      } catch (const rgnav::FileError& e) {
        CPPUNIT_ASSERT(std::string(e.what()).find(path) != std::string::npos);
      }
    }
  }

  void zeroCapIsRejected() {
    TempDir dir;
    rgnav::testing::writeFile(dir.file("f"), "x\n");
    CPPUNIT_ASSERT_THROW(LineReader(dir.file("f"), 0), rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(LineReaderTest);
