// Tests connectedComponents: 8-connectivity, the minimum size, numbering by first cell, and a
// brute-force flood fill on random masks.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <opencv2/core.hpp>
#include <random>
#include <vector>

#include "core/common/Errors.h"
#include "core/raster/Components.h"

using namespace rgnav;

namespace {

// Reference labels: depth-first 8-connected fills, seeded in row-major order.
std::vector<int> bruteForceLabels(const cv::Mat& mask) {
  std::vector<int> labels(mask.total(), -1);
  int next = 0;
  for (int r0 = 0; r0 < mask.rows; ++r0)
    for (int c0 = 0; c0 < mask.cols; ++c0) {
      if (!mask.at<std::uint8_t>(r0, c0) || labels[std::size_t(r0 * mask.cols + c0)] >= 0) continue;
      std::vector<std::pair<int, int>> stack{{r0, c0}};
      labels[std::size_t(r0 * mask.cols + c0)] = next;
      while (!stack.empty()) {
        const auto [r, c] = stack.back();
        stack.pop_back();
        for (int dr = -1; dr <= 1; ++dr)
          for (int dc = -1; dc <= 1; ++dc) {
            const int rr = r + dr, cc = c + dc;
            if (rr < 0 || cc < 0 || rr >= mask.rows || cc >= mask.cols || !mask.at<std::uint8_t>(rr, cc)) continue;
            int& label = labels[std::size_t(rr * mask.cols + cc)];
            if (label < 0) {
              label = next;
              stack.emplace_back(rr, cc);
            }
          }
      }
      ++next;
    }
  return labels;
}

}  // namespace

class ComponentsTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ComponentsTest);
  CPPUNIT_TEST(diagonalCellsJoinAndSmallSetsDrop);
  CPPUNIT_TEST(matchesBruteForceOnRandomMasks);
  CPPUNIT_TEST(rejectsAWrongMask);
  CPPUNIT_TEST_SUITE_END();

 public:
  void diagonalCellsJoinAndSmallSetsDrop() {
    const cv::Mat mask = (cv::Mat_<std::uint8_t>(4, 6) << 0, 0, 0, 0, 0, 9,  //
                          1, 0, 0, 0, 0, 0,                                   //
                          0, 1, 0, 0, 1, 1,                                   //
                          0, 0, 0, 0, 1, 1);
    const Components c = connectedComponents(mask, 2);
    CPPUNIT_ASSERT_EQUAL(2, c.count());
    CPPUNIT_ASSERT_EQUAL(-1, c.labels[5]);  // the single cell at the top right is dropped
    CPPUNIT_ASSERT_EQUAL(0, c.labels[6]);   // first kept cell in row-major order: number 0
    CPPUNIT_ASSERT_EQUAL(0, c.labels[13]);  // its diagonal neighbour joins it
    CPPUNIT_ASSERT_EQUAL(1, c.labels[16]);
    CPPUNIT_ASSERT_EQUAL(2, c.sizes[0]);
    CPPUNIT_ASSERT_EQUAL(4, c.sizes[1]);
    CPPUNIT_ASSERT_EQUAL(-1, c.labels[0]);
  }

  void matchesBruteForceOnRandomMasks() {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 20; ++trial) {
      cv::Mat mask(23 + trial, 31, CV_8UC1);
      for (auto p = mask.data; p != mask.data + mask.total(); ++p) *p = rng() % 100 < 45 ? 1 : 0;
      const std::vector<int> expected = bruteForceLabels(mask);
      const Components c = connectedComponents(mask, 1);
      CPPUNIT_ASSERT(c.labels == expected);
      for (int k = 0; k < c.count(); ++k)
        CPPUNIT_ASSERT_EQUAL(int(std::count(expected.begin(), expected.end(), k)), c.sizes[std::size_t(k)]);
    }
  }

  void rejectsAWrongMask() {
    CPPUNIT_ASSERT_THROW(connectedComponents(cv::Mat(), 1), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(connectedComponents(cv::Mat(3, 3, CV_32F, cv::Scalar(1)), 1), InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(ComponentsTest);
