// CrowdPicture on a tiny walled grid with two goals, the first reached and the second not: the
// file is written at about 40 px per metre with north at the top, a point of a driven path has
// its goal's colour, the failed goal's cross (where the robot ended) is red, and the reached goal
// has no red ring.
#include <cppunit/extensions/HelperMacros.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "core/logs/LogTestFiles.h"
#include "tests/eval/crowd/CrowdPicture.h"

using namespace rgnav;

namespace {

// 5 m x 3 m at 0.05 m, walled all round.
OccupancyGrid walledGrid() {
  OccupancyGrid grid(100, 60, 0.05, {-1.0, 2.0});
  for (int c = 0; c < grid.width(); ++c) grid.set({c, 0}, Cell::Occupied), grid.set({c, grid.height() - 1}, Cell::Occupied);
  for (int r = 0; r < grid.height(); ++r) grid.set({0, r}, Cell::Occupied), grid.set({grid.width() - 1, r}, Cell::Occupied);
  return grid;
}

CrowdOutcome twoGoals() {
  GoalOutcome reached;
  reached.goal = {3.0, 3.0};
  reached.reached = true;
  reached.path = {{0.0, 3.0}, {1.5, 3.0}, {3.0, 3.0}};
  GoalOutcome failed;
  failed.goal = {0.0, 4.3};
  failed.path = {{3.0, 3.0}, {3.0, 4.3}, {2.0, 4.3}};
  return {{reached, failed}};
}

cv::Vec3b colourAt(const cv::Mat& image, const OccupancyGrid& grid, const Eigen::Vector2d& p) {
  const cv::Point px = crowdPicturePixel(grid, p);
  return image.at<cv::Vec3b>(px);
}

cv::Vec3b bgr(const cv::Scalar& s) {
  return {static_cast<std::uint8_t>(s[0]), static_cast<std::uint8_t>(s[1]), static_cast<std::uint8_t>(s[2])};
}

}  // namespace

class CrowdPictureTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(CrowdPictureTest);
  CPPUNIT_TEST(showsPathsGoalsAndFailures);
  CPPUNIT_TEST_SUITE_END();

 public:
  void showsPathsGoalsAndFailures() {
    const testing::TempDir dir;
    const std::string file = dir.file("crowd.png");
    const OccupancyGrid grid = walledGrid();
    writeCrowdPicture(file, grid, {0.0, 3.0, 0.0}, twoGoals());
    CPPUNIT_ASSERT(std::filesystem::exists(file));
    const cv::Mat image = cv::imread(file, cv::IMREAD_COLOR);
    CPPUNIT_ASSERT_EQUAL(200, image.cols);
    CPPUNIT_ASSERT_EQUAL(120, image.rows);
    // North at the top: the grid's top wall is the image's first row, the room below it is free.
    CPPUNIT_ASSERT(colourAt(image, grid, {1.5, 4.99}) == cv::Vec3b(70, 70, 70));
    CPPUNIT_ASSERT(colourAt(image, grid, {1.5, 4.6}) == cv::Vec3b(255, 255, 255));
    CPPUNIT_ASSERT(colourAt(image, grid, {1.5, 3.0}) == bgr(crowdGoalColour(0)));
    CPPUNIT_ASSERT(colourAt(image, grid, {3.0, 3.7}) == bgr(crowdGoalColour(1)));
    CPPUNIT_ASSERT(colourAt(image, grid, {2.0, 4.3}) == bgr(crowdFailureColour()));
    CPPUNIT_ASSERT(colourAt(image, grid, {3.0, 3.0 + 12.5 / 40.0}) != bgr(crowdFailureColour()));
    CPPUNIT_ASSERT(crowdGoalColour(0) != crowdGoalColour(1));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(CrowdPictureTest);
