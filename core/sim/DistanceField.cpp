// Exact squared Euclidean distance transform: a 1D distance per column, then the lower envelope
// of parabolas per row (Felzenszwalb & Huttenlocher 2012).
#include "core/sim/DistanceField.h"

#include <algorithm>
#include <limits>

namespace rgnav {
namespace {

constexpr double kFar = 1e20;  // "no blocked cell in this column", far above any real square

// d[q] = min over p of (q - p)^2 + f[p], for one row; v and z are scratch (n and n + 1 long).
void lowerEnvelope(const std::vector<double>& f, std::vector<double>& d, std::vector<int>& v, std::vector<double>& z) {
  const int n = static_cast<int>(f.size());
  const auto intersection = [&](int q, int p) { return ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * (q - p)); };
  int k = 0;
  v[0] = 0;
  z[0] = -std::numeric_limits<double>::infinity();
  z[1] = std::numeric_limits<double>::infinity();
  for (int q = 1; q < n; ++q) {
    double s = intersection(q, v[k]);
    while (s <= z[k]) s = intersection(q, v[--k]);  // z[0] = -inf ends the loop
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = std::numeric_limits<double>::infinity();
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    d[q] = double(q - v[k]) * (q - v[k]) + f[v[k]];
  }
}

}  // namespace

std::vector<float> squaredDistanceToBlocked(const OccupancyGrid& grid) {
  if (grid.cells().empty()) return {};
  const int w = grid.width(), h = grid.height();
  const auto index = [w](int col, int row) {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(w) + static_cast<std::size_t>(col);
  };
  // Column pass: squared distance to the nearest blocked cell in the same column.
  std::vector<double> columnSquared(grid.cells().size());
  for (int col = 0; col < w; ++col) {
    double gap = kFar;
    for (int row = 0; row < h; ++row) {
      gap = grid.at({col, row}) != Cell::Free ? 0.0 : gap + 1.0;
      columnSquared[index(col, row)] = gap;
    }
    gap = kFar;
    for (int row = h - 1; row >= 0; --row) {
      gap = grid.at({col, row}) != Cell::Free ? 0.0 : gap + 1.0;
      columnSquared[index(col, row)] = std::min(columnSquared[index(col, row)], gap);
    }
    for (int row = 0; row < h; ++row) {
      double& g = columnSquared[index(col, row)];
      g = g >= kFar ? kFar : g * g;
    }
  }
  // Row pass.
  std::vector<float> out(grid.cells().size());
  const std::size_t rowLength = grid.cells().size() / static_cast<std::size_t>(std::max(h, 1));
  std::vector<double> f(rowLength), d(rowLength), z(rowLength + 1);
  std::vector<int> v(rowLength);
  for (int row = 0; row < h; ++row) {
    for (int col = 0; col < w; ++col) f[col] = columnSquared[index(col, row)];
    lowerEnvelope(f, d, v, z);
    for (int col = 0; col < w; ++col) {
      const double value = d[col];
      out[index(col, row)] = value >= kFar ? kNoBlockedCell : static_cast<float>(value);
    }
  }
  return out;
}

}  // namespace rgnav
