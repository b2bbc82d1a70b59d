// SplitAndMerge: partitions a run of consecutive scan points (no breakpoint inside) into
// straight pieces. Split: iterative end-point fit, i.e. a run is cut at the point farthest from
// the chord between its first and last point while that distance exceeds splitDistanceM.
// Merge: neighbouring pieces are joined again while the total-least-squares line through both
// keeps every point within splitDistanceM. Finally a point at the border of two pieces moves to
// the piece whose line is nearer (the farthest point from a chord may miss a corner by a point
// or two). (Thesis 5.2 leaves line extraction to ScanStudio;
// this is the classic split-and-merge of Pavlidis & Horowitz with a TLS fit.)
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

namespace rgnav {

// Half-open index ranges of `points`, in order, partitioning all of it (a piece may hold a single
// point, e.g. an outlier between two corners).
std::vector<std::pair<std::size_t, std::size_t>> splitAndMerge(std::span<const Eigen::Vector2d> points,
                                                               double splitDistanceM);

}  // namespace rgnav
