// Moments of a region's freespace; see FreespaceMoments.h.
#include "core/rgmap/describe/FreespaceMoments.h"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace rgnav {
namespace {

// The share of lattice cell (i, j) that belongs to the freespace.
double weight(const RegionFreespace& f, int i, int j) {
  switch (f.cell(i, j)) {
    case FreespaceCell::Free:
      return 1.0;
    case FreespaceCell::Occupied:
      return f.cell(i + 1, j) == FreespaceCell::Free || f.cell(i - 1, j) == FreespaceCell::Free ||
                     f.cell(i, j + 1) == FreespaceCell::Free || f.cell(i, j - 1) == FreespaceCell::Free
                 ? 0.5
                 : 0.0;
    case FreespaceCell::Unknown:
      break;
  }
  return 0.0;
}

}  // namespace

FreespaceMoments freespaceMoments(const RegionFreespace& freespace) {
  // Sums over cell indices relative to the window corner (small numbers, no cancellation),
  // converted to metres at the end.
  const CellWindow& w = freespace.window();
  double n = 0.0, sc = 0.0, sr = 0.0, scc = 0.0, srr = 0.0, scr = 0.0;
  for (int r = 0; r < w.height; ++r)
    for (int c = 0; c < w.width; ++c) {
      const double m = weight(freespace, w.col0 + c, w.row0 + r);
      n += m;
      sc += m * c;
      sr += m * r;
      scc += m * c * c;
      srr += m * r * r;
      scr += m * c * r;
    }
  FreespaceMoments out;
  if (n == 0.0) return out;
  const double s = freespace.cellSizeM();
  const Eigen::Vector2d meanCell(sc / n, sr / n);
  out.areaM2 = n * s * s;
  out.centroid = freespace.cellCenter(w.col0, w.row0) + s * meanCell;
  const double cxy = scr / n - meanCell.x() * meanCell.y();
  out.covariance << scc / n - meanCell.x() * meanCell.x(), cxy, cxy, srr / n - meanCell.y() * meanCell.y();
  out.covariance = s * s * (out.covariance + Eigen::Matrix2d::Identity() / 12.0);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(out.covariance);
  out.minorVariance = eigen.eigenvalues()(0);
  out.majorVariance = eigen.eigenvalues()(1);
  const Eigen::Vector2d major = eigen.eigenvectors().col(1);
  double angle = std::atan2(major.y(), major.x());
  if (angle < 0.0) angle += M_PI;
  out.majorAxisAngleRad = angle >= M_PI ? 0.0 : angle;
  return out;
}

}  // namespace rgnav
