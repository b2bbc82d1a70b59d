// connectedComponents: OpenCV labels the components; the renumbering here is ours because
// OpenCV's label order depends on its scan (block-wise and, on large images, parallel stripes),
// while rooms and blobs keep the order of their first cell so that their numbers are stable.
#include "core/raster/Components.h"

#include <opencv2/imgproc.hpp>

#include "core/common/Errors.h"

namespace rgnav {

Components connectedComponents(const cv::Mat& mask, int minSize) {
  if (mask.empty() || mask.type() != CV_8UC1)
    throw InvalidArgumentError("connectedComponents: the mask must be a non-empty 8-bit single-channel image");
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
  constexpr int kUnseen = -2;
  std::vector<int> renumber(static_cast<std::size_t>(n), kUnseen);
  renumber[0] = -1;  // the background
  Components out;
  out.labels.resize(mask.total());
  std::size_t i = 0;
  for (int row = 0; row < labels.rows; ++row) {
    const int* label = labels.ptr<int>(row);
    for (int col = 0; col < labels.cols; ++col, ++i) {
      int& number = renumber[static_cast<std::size_t>(label[col])];
      if (number == kUnseen) {
        const int area = stats.at<int>(label[col], cv::CC_STAT_AREA);
        number = area >= minSize ? out.count() : -1;
        if (number >= 0) out.sizes.push_back(area);
      }
      out.labels[i] = number;
    }
  }
  return out;
}

}  // namespace rgnav
