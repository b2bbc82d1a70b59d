// Tests the tour over a world's ground truth: with the grid's geometry it is the tour over the
// ground truth's room labels; a ground truth of another size or origin is an InvalidArgumentError.
#include "core/sim/GroundTruthTour.h"

#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"

using rgnav::Cell;
using rgnav::GroundTruth;
using rgnav::OccupancyGrid;

namespace {

// Two free 1 m x 1 m rooms side by side (columns 0-19 room 0, 20-39 room 1) in a walled grid.
struct World {
  OccupancyGrid grid{42, 22, 0.05, {-0.05, -0.05}, Cell::Occupied};
  GroundTruth truth;

  World() {
    truth.width = grid.width();
    truth.height = grid.height();
    truth.resolution = grid.resolution();
    truth.origin = grid.origin();
    truth.roomCount = 2;
    truth.labels.assign(grid.cells().size(), -1);
    for (int row = 1; row <= 20; ++row) {
      for (int col = 1; col <= 40; ++col) {
        grid.set({col, row}, Cell::Free);
        truth.labels[rgnav::rowMajor({col, row}, grid.width())] = col <= 20 ? 0 : 1;
      }
    }
  }
};

}  // namespace

class GroundTruthTourTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(GroundTruthTourTest);
  CPPUNIT_TEST(toursTheGroundTruthRooms);
  CPPUNIT_TEST(otherGeometryIsInvalidArgument);
  CPPUNIT_TEST_SUITE_END();

 public:
  void toursTheGroundTruthRooms() {
    const World w;
    const rgnav::GridPlannerConfig config{.robotRadius = 0.1};
    const rgnav::Tour tour = rgnav::planTour(w.grid, w.truth, {0.3, 0.5, 0.0}, config);
    const rgnav::Tour byLabels = rgnav::planTour(w.grid, w.truth.labels, 2, {0.3, 0.5, 0.0}, config);
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, tour.visits.size());
    CPPUNIT_ASSERT_EQUAL(0, tour.visits[0].room);
    CPPUNIT_ASSERT_EQUAL(1, tour.visits[1].room);
    CPPUNIT_ASSERT_EQUAL(byLabels.route.size(), tour.route.size());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(byLabels.route.back().x, tour.route.back().x, 1e-12);
  }

  void otherGeometryIsInvalidArgument() {
    World shifted;
    shifted.truth.origin.x += 1.0;
    CPPUNIT_ASSERT_THROW(rgnav::planTour(shifted.grid, shifted.truth, {0.3, 0.5, 0.0}), rgnav::InvalidArgumentError);
    World wider;
    wider.truth.width += 1;
    CPPUNIT_ASSERT_THROW(rgnav::planTour(wider.grid, wider.truth, {0.3, 0.5, 0.0}), rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(GroundTruthTourTest);
