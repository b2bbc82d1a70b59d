// Image files on OpenCV (cv::imread / cv::imencode): readGrayImage loads any image OpenCV reads
// (PNG, binary P5 and plain P2 PGM among them, recognised by content, not by file name) as 8-bit
// gray exactly as imread(IMREAD_GRAYSCALE) does, which the floor-plan benchmark's encoding
// assumes (floorplans/SOURCES.md: alpha dropped, 16-bit samples cut to the high byte, gray =
// 0.299 R + 0.587 G + 0.114 B). writeImage writes an 8-bit gray or BGR Mat (OpenCV's channel
// order) as a PNG or a binary P5 PGM (ROS map_server maps), chosen by the file name, atomically
// through core/common/AtomicFile.
#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace rgnav {

// CV_8UC1, row 0 at the top. A missing or unreadable file is a FileError, anything OpenCV cannot
// decode a FormatError; both name the path.
cv::Mat readGrayImage(const std::string& path);

// `image` is CV_8UC1 or CV_8UC3 (BGR); `path` ends in .png or .pgm (a PGM must be gray). An
// empty image or another type or ending is an InvalidArgumentError, a failed write a FileError;
// both name the path.
void writeImage(const std::string& path, const cv::Mat& image);

}  // namespace rgnav
