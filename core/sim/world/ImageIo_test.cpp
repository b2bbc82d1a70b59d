// Tests the image files of the simulator's worlds: PNG and PGM (P5/P2) round trips, colour to
// gray as OpenCV does it, 16-bit PGM, the real benchmark PNG flavours, and typed errors.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <random>

#include "core/logs/LogTestFiles.h"
#include "core/sim/world/FileBytes.h"
#include "core/sim/world/ImageFile.h"
#include "core/sim/world/PgmIo.h"
#include "core/sim/world/PngIo.h"

using namespace rgnav;
using rgnav::testing::TempDir;
using rgnav::testing::writeFile;

namespace {

GrayImage randomGray(int width, int height, unsigned seed) {
  GrayImage image(width, height);
  std::mt19937 rng(seed);
  for (auto& p : image.pixels()) p = static_cast<std::uint8_t>(rng() & 0xff);
  return image;
}

template <typename Error, typename Call>
void expectErrorNaming(const std::string& path, Call call) {
  try {
    call();
    CPPUNIT_FAIL("no error for " + path);
  } catch (const Error& e) {
    CPPUNIT_ASSERT_MESSAGE(e.what(), std::string(e.what()).find(path) != std::string::npos);
  }
}

std::string testMap(const std::string& name) {
  return rgnav::testing::sharedData("floorplans/ipa_room_segmentation/test_maps/" + name);
}

}  // namespace

class ImageIoTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ImageIoTest);
  CPPUNIT_TEST(grayPngRoundTrip);
  CPPUNIT_TEST(rgbPngReadsAsOpenCvGray);
  CPPUNIT_TEST(pgmRoundTripsBinaryAndAscii);
  CPPUNIT_TEST(pgmSixteenBitAndComments);
  CPPUNIT_TEST(readsEveryBenchmarkPngFlavour);
  CPPUNIT_TEST(missingAndDamagedFilesAreTypedErrors);
  CPPUNIT_TEST_SUITE_END();

 public:
  void grayPngRoundTrip() {
    TempDir dir;
    const GrayImage image = randomGray(37, 23, 1);
    writePng(dir.file("a.png"), image);
    CPPUNIT_ASSERT(readGrayImage(dir.file("a.png")) == image);
  }

  void rgbPngReadsAsOpenCvGray() {
    TempDir dir;
    RgbImage image(5, 1);
    const std::uint8_t colours[5][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}, {250, 250, 250}};
    for (int i = 0; i < 5; ++i) {
      for (int c = 0; c < 3; ++c) image.set(i, 0, colours[i][c], c);
    }
    writePng(dir.file("rgb.png"), image);
    const GrayImage gray = readGrayImage(dir.file("rgb.png"));
    // libpng's 15-bit fixed-point 0.299 R + 0.587 G + 0.114 B, truncated: what OpenCV's
    // imread(IMREAD_GRAYSCALE) returns for these colours.
    const int expected[5] = {76, 149, 29, 255, 250};
    for (int i = 0; i < 5; ++i) CPPUNIT_ASSERT_EQUAL(expected[i], int(gray.at(i, 0)));
  }

  void pgmRoundTripsBinaryAndAscii() {
    TempDir dir;
    const GrayImage image = randomGray(41, 19, 2);
    writePgm(dir.file("b.pgm"), image, PgmEncoding::Binary);
    writePgm(dir.file("a.pgm"), image, PgmEncoding::Ascii);
    CPPUNIT_ASSERT(readGrayImage(dir.file("b.pgm")) == image);
    CPPUNIT_ASSERT(readGrayImage(dir.file("a.pgm")) == image);
  }

  void pgmSixteenBitAndComments() {
    TempDir dir;
    writeFile(dir.file("w.pgm"), std::string("P5\n# made by hand\n2 1\n# max\n65535\n") + '\xff' + '\xff' + '\x80' + '\x00');
    const GrayImage wide = readGrayImage(dir.file("w.pgm"));
    CPPUNIT_ASSERT_EQUAL(255, int(wide.at(0, 0)));
    CPPUNIT_ASSERT_EQUAL(128, int(wide.at(1, 0)));
    writeFile(dir.file("p.pgm"), "P2 # plain\n3 1 15\n0 15 # end of row\n 5\n");
    const GrayImage plain = readGrayImage(dir.file("p.pgm"));
    CPPUNIT_ASSERT_EQUAL(0, int(plain.at(0, 0)));
    CPPUNIT_ASSERT_EQUAL(255, int(plain.at(1, 0)));
    CPPUNIT_ASSERT_EQUAL(85, int(plain.at(2, 0)));
  }

  // Gray+alpha, 8-bit gray, RGB, RGBA, 16-bit RGBA and palette PNGs of the shared data.
  void readsEveryBenchmarkPngFlavour() {
    const struct {
      const char* file;
      int width, height;
    } maps[] = {{"Freiburg52_scan.png", 643, 354}, {"office_b.png", 1194, 685},
                {"office_b_furnitures.png", 1194, 685}, {"office_a.png", 1194, 685},
                {"lab_b.png", 1237, 672}, {"lab_e.png", 875, 685}};
    for (const auto& map : maps) {
      const GrayImage image = readGrayImage(testMap(map.file));
      CPPUNIT_ASSERT_EQUAL(map.width, image.width());
      CPPUNIT_ASSERT_EQUAL(map.height, image.height());
      const auto free = std::count_if(image.pixels().begin(), image.pixels().end(), [](auto p) { return p >= 250; });
      CPPUNIT_ASSERT_MESSAGE(map.file, free > 1000 && free < long(image.pixels().size()) - 1000);
    }
  }

  void missingAndDamagedFilesAreTypedErrors() {
    TempDir dir;
    expectErrorNaming<FileError>(dir.file("none.png"), [&] { readGrayImage(dir.file("none.png")); });
    expectErrorNaming<FileError>(dir.path(), [&] { readGrayImage(dir.path()); });

    writePng(dir.file("ok.png"), randomGray(64, 64, 3));
    const std::string png = readFileBytes(dir.file("ok.png"));
    writeFile(dir.file("cut.png"), png.substr(0, png.size() / 2));
    expectErrorNaming<FormatError>(dir.file("cut.png"), [&] { readGrayImage(dir.file("cut.png")); });
    std::string flipped = png;
    flipped[20] ^= 0x55;  // inside the IHDR chunk: the CRC no longer matches
    writeFile(dir.file("crc.png"), flipped);
    expectErrorNaming<FormatError>(dir.file("crc.png"), [&] { readGrayImage(dir.file("crc.png")); });

    writeFile(dir.file("text.png"), "hello, not an image");
    expectErrorNaming<FormatError>(dir.file("text.png"), [&] { readGrayImage(dir.file("text.png")); });
    writeFile(dir.file("short.pgm"), "P5\n4 4\n255\n0123");
    expectErrorNaming<FormatError>(dir.file("short.pgm"), [&] { readGrayImage(dir.file("short.pgm")); });
    writeFile(dir.file("bad.pgm"), "P2\n2 2\n255\n0 1 2 x\n");
    try {
      readGrayImage(dir.file("bad.pgm"));
      CPPUNIT_FAIL("no error for a bad pixel value");
    } catch (const FormatError& e) {
      CPPUNIT_ASSERT_EQUAL(std::size_t(4), e.line());
    }
    writeFile(dir.file("big.pgm"), "P2\n1 1\n15\n16\n");
    expectErrorNaming<FormatError>(dir.file("big.pgm"), [&] { readGrayImage(dir.file("big.pgm")); });
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(ImageIoTest);
