// Tests the raster library's image files: gray and BGR PNG and PGM (P5 written, P5/P2 read)
// round trips, colour to gray as imread(IMREAD_GRAYSCALE) does it, 16-bit PGM, the real benchmark
// PNG flavours, and typed errors naming the path.
#include <cppunit/extensions/HelperMacros.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <random>

#include "core/common/AtomicFile.h"
#include "core/common/Errors.h"
#include "core/logs/LogTestFiles.h"
#include "core/raster/ImageFile.h"

using namespace rgnav;
using rgnav::testing::TempDir;
using rgnav::testing::writeFile;

namespace {

cv::Mat randomImage(int width, int height, int type, unsigned seed) {
  cv::Mat image(height, width, type);
  std::mt19937 rng(seed);
  for (auto p = image.data; p != image.data + image.total() * image.elemSize(); ++p) *p = static_cast<std::uint8_t>(rng() & 0xff);
  return image;
}

bool same(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::countNonZero(a.reshape(1) != b.reshape(1)) == 0;
}

std::string fileBytes(const std::string& path) { return readCheckpoint(path).value(); }

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

class ImageFileTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ImageFileTest);
  CPPUNIT_TEST(grayPngAndPgmRoundTrip);
  CPPUNIT_TEST(bgrPngRoundTripAndOpenCvGray);
  CPPUNIT_TEST(pgmSixteenBitPlainAndComments);
  CPPUNIT_TEST(readsEveryBenchmarkPngFlavour);
  CPPUNIT_TEST(missingAndDamagedFilesAreTypedErrors);
  CPPUNIT_TEST(unwritableImagesAreTypedErrors);
  CPPUNIT_TEST_SUITE_END();

 public:
  void grayPngAndPgmRoundTrip() {
    TempDir dir;
    const cv::Mat image = randomImage(37, 23, CV_8UC1, 1);
    writeImage(dir.file("a.png"), image);
    writeImage(dir.file("a.pgm"), image);
    CPPUNIT_ASSERT(same(readGrayImage(dir.file("a.png")), image));
    CPPUNIT_ASSERT(same(readGrayImage(dir.file("a.pgm")), image));
    CPPUNIT_ASSERT_EQUAL(std::string("P5"), fileBytes(dir.file("a.pgm")).substr(0, 2));  // binary, as map_server reads
  }

  void bgrPngRoundTripAndOpenCvGray() {
    TempDir dir;
    cv::Mat image(1, 5, CV_8UC3);
    const cv::Vec3b rgb[5] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}, {250, 250, 250}};
    for (int i = 0; i < 5; ++i) image.at<cv::Vec3b>(0, i) = {rgb[i][2], rgb[i][1], rgb[i][0]};
    writeImage(dir.file("rgb.png"), image);
    const cv::Mat gray = readGrayImage(dir.file("rgb.png"));
    // 0.299 R + 0.587 G + 0.114 B in libpng's fixed point, truncated: what the benchmark's
    // encoding assumes (floorplans/SOURCES.md).
    const int expected[5] = {76, 149, 29, 255, 250};
    for (int i = 0; i < 5; ++i) CPPUNIT_ASSERT_EQUAL(expected[i], int(gray.at<std::uint8_t>(0, i)));
    const cv::Mat colour = randomImage(17, 9, CV_8UC3, 4);
    writeImage(dir.file("colour.png"), colour);
    CPPUNIT_ASSERT(same(cv::imread(dir.file("colour.png"), cv::IMREAD_COLOR), colour));
  }

  void pgmSixteenBitPlainAndComments() {
    TempDir dir;
    writeFile(dir.file("w.pgm"), std::string("P5\n# made by hand\n2 1\n# max\n65535\n") + '\xff' + '\xff' + '\x80' + '\x00');
    const cv::Mat wide = readGrayImage(dir.file("w.pgm"));
    CPPUNIT_ASSERT_EQUAL(255, int(wide.at<std::uint8_t>(0, 0)));
    CPPUNIT_ASSERT_EQUAL(128, int(wide.at<std::uint8_t>(0, 1)));
    writeFile(dir.file("p.pgm"), "P2 # plain\n3 1 15\n0 15 # end of row\n 5\n");
    const cv::Mat plain = readGrayImage(dir.file("p.pgm"));
    CPPUNIT_ASSERT_EQUAL(0, int(plain.at<std::uint8_t>(0, 0)));
    CPPUNIT_ASSERT_EQUAL(255, int(plain.at<std::uint8_t>(0, 1)));
    CPPUNIT_ASSERT_EQUAL(85, int(plain.at<std::uint8_t>(0, 2)));
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
      const cv::Mat image = readGrayImage(testMap(map.file));
      CPPUNIT_ASSERT_EQUAL(CV_8UC1, image.type());
      CPPUNIT_ASSERT_EQUAL(map.width, image.cols);
      CPPUNIT_ASSERT_EQUAL(map.height, image.rows);
      const int free = cv::countNonZero(image >= 250);
      CPPUNIT_ASSERT_MESSAGE(map.file, free > 1000 && free < int(image.total()) - 1000);
    }
  }

  void missingAndDamagedFilesAreTypedErrors() {
    TempDir dir;
    expectErrorNaming<FileError>(dir.file("none.png"), [&] { readGrayImage(dir.file("none.png")); });
    expectErrorNaming<FileError>(dir.path(), [&] { readGrayImage(dir.path()); });

    writeImage(dir.file("ok.png"), randomImage(64, 64, CV_8UC1, 3));
    const std::string png = fileBytes(dir.file("ok.png"));
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
    expectErrorNaming<FormatError>(dir.file("bad.pgm"), [&] { readGrayImage(dir.file("bad.pgm")); });
  }

  void unwritableImagesAreTypedErrors() {
    TempDir dir;
    const cv::Mat gray = randomImage(4, 4, CV_8UC1, 5);
    expectErrorNaming<InvalidArgumentError>(dir.file("a.jpg"), [&] { writeImage(dir.file("a.jpg"), gray); });
    expectErrorNaming<InvalidArgumentError>(dir.file("e.png"), [&] { writeImage(dir.file("e.png"), cv::Mat()); });
    expectErrorNaming<InvalidArgumentError>(dir.file("c.pgm"),
                                            [&] { writeImage(dir.file("c.pgm"), randomImage(4, 4, CV_8UC3, 6)); });
    expectErrorNaming<FileError>(dir.file("no/such/dir.png"), [&] { writeImage(dir.file("no/such/dir.png"), gray); });
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(ImageFileTest);
