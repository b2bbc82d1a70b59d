// Tests the RG Map's PNG export on the map of the two-room tour: the file reads back (core/raster) at
// the size of the picture's extent, each region's colour at its freespace centroid, doors drawn
// on the true door lines, a ring corridor labelled in its freespace, bad resolutions refused,
// overlays painted over everything.
#include "core/rgmap/export/RgMapPng.h"

#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/common/Errors.h"
#include "core/lines/ScanPoints.h"
#include "core/logs/LogTestFiles.h"
#include "core/raster/ImageFile.h"
#include "core/rgmap/export/MapCanvas.h"
#include "core/rgmap/export/MapColours.h"
#include "core/rgmap/export/MapExtent.h"
#include "core/rgmap/export/testing/ExportedFloor.h"

using namespace rgnav;

namespace {

Rgb pixel(const cv::Mat& bgr, const Eigen::Vector2i& p) {
  const cv::Vec3b v = bgr.at<cv::Vec3b>(p.y(), p.x());
  return {v[2], v[1], v[0]};
}

// Gray as readGrayImage reads colour files (ITU-R 601 luma).
int luma(const Rgb& c) { return int(std::lround(0.299 * c.r + 0.587 * c.g + 0.114 * c.b)); }

}  // namespace

class RgMapPngTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RgMapPngTest);
  CPPUNIT_TEST(fileReadsBackAtTheExtentsSize);
  CPPUNIT_TEST(regionColoursAtTheirCentroids);
  CPPUNIT_TEST(doorsAreDrawnOnTheDoorLines);
  CPPUNIT_TEST(ringIsLabelledInItsFreespace);
  CPPUNIT_TEST(badResolutionIsRefused);
  CPPUNIT_TEST(overlaysArePaintedOverTheMap);
  CPPUNIT_TEST_SUITE_END();

 public:
  void setUp() override {
    snapshot_ = snapshotOf(rgnav::testing::twoRoomMap());
    image_ = renderRgMap(snapshot_, 0.05);
    canvas_ = std::make_unique<MapCanvas>(pictureExtent(snapshot_), 0.05, kBackgroundColour);
  }

  void fileReadsBackAtTheExtentsSize() {
    rgnav::testing::TempDir dir;
    exportRgMapPng(dir.file("map.png"), snapshot_, 0.05);
    const cv::Mat read = readGrayImage(dir.file("map.png"));
    const Eigen::Vector2d size = pictureExtent(snapshot_).sizes();
    CPPUNIT_ASSERT_EQUAL(int(std::ceil(size.x() / 0.05)), read.cols);
    CPPUNIT_ASSERT_EQUAL(int(std::ceil(size.y() / 0.05)), read.rows);
    CPPUNIT_ASSERT_EQUAL(image_.cols, read.cols);
    // The floor is 12 x 6 m; the picture adds half a metre on every side.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(13.0 / 0.05, read.cols, 8);
    for (const RegionSnapshot& r : snapshot_.regions) {
      const Eigen::Vector2i at = canvas_->pixelOf(r.labelPosition());
      CPPUNIT_ASSERT(std::abs(luma(regionColour(r.region.id)) - int(read.at<std::uint8_t>(at.y(), at.x()))) <= 1);
    }
  }

  void regionColoursAtTheirCentroids() {
    for (const RegionSnapshot& r : snapshot_.regions) {
      const Eigen::Vector2i at = canvas_->pixelOf(r.labelPosition());
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc)
          CPPUNIT_ASSERT(pixel(image_, at + Eigen::Vector2i(dc, dr)) == regionColour(r.region.id));
    }
    CPPUNIT_ASSERT(regionColour(RegionId{1}) != regionColour(RegionId{2}) && regionColour(RegionId{2}) != regionColour(RegionId{3}) &&
                   regionColour(RegionId{1}) != regionColour(RegionId{3}));
  }

  void overlaysArePaintedOverTheMap() {
    const Rgb green{0, 160, 60};
    const cv::Mat image = renderRgMap(snapshot_, 0.05, {{{{1.0, 1.0}, {9.0, 1.0}, {9.0, 4.0}}, green, 0.1, 0.0, "path"}});
    for (const Eigen::Vector2d& p : {Eigen::Vector2d(5.0, 1.0), Eigen::Vector2d(9.0, 3.0), Eigen::Vector2d(9.0, 2.0)})
      CPPUNIT_ASSERT(pixel(image, canvas_->pixelOf(p)) == green);  // over freespace, and over door 12
    CPPUNIT_ASSERT(pixel(image, canvas_->pixelOf({5.0, 1.5})) != green);
  }

  void doorsAreDrawnOnTheDoorLines() {
    for (const double x : {4.0, 9.0}) CPPUNIT_ASSERT(pixel(image_, canvas_->pixelOf({x, 2.0})) == kDoorColour);
    CPPUNIT_ASSERT(pixel(image_, canvas_->pixelOf({-0.3, -0.3})) == kBackgroundColour);
  }

  void ringIsLabelledInItsFreespace() {
    const RgMapSnapshot ring = snapshotOf(rgnav::testing::ringMap());
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), ring.regions.size());
    const RegionSnapshot& r = ring.regions.front();
    // The centroid lies in the block the corridor runs around; the label goes to the corridor.
    CPPUNIT_ASSERT(!r.description.freespace.isFreeAt(r.description.moments.centroid));
    const Eigen::Vector2d label = r.labelPosition();
    CPPUNIT_ASSERT(r.description.freespace.isFreeAt(transformPoint(inverse(r.region.frame), label)));
    const MapCanvas canvas(pictureExtent(ring), 0.05, kBackgroundColour);
    CPPUNIT_ASSERT(pixel(renderRgMap(ring, 0.05), canvas.pixelOf(label)) == regionColour(r.region.id));
  }

  void badResolutionIsRefused() {
    CPPUNIT_ASSERT_THROW(renderRgMap(snapshot_, 0.0), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(renderRgMap(snapshot_, -1.0), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(renderRgMap(snapshot_, 1e-5), InvalidArgumentError);
  }

 private:
  RgMapSnapshot snapshot_;
  cv::Mat image_;
  std::unique_ptr<MapCanvas> canvas_;
};

CPPUNIT_TEST_SUITE_REGISTRATION(RgMapPngTest);
