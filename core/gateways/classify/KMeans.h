// k-means clustering (Lloyd's algorithm; Bishop 2006, section 9.1) from given start centres, as
// the thesis uses it to find the Gaussians of the gateway HMMs (4.1.3.3). Deterministic: ties go
// to the lower cluster index and a cluster that loses all its points keeps its centre.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace rgnav {

struct KMeansResult {
  Eigen::MatrixXd centres;               // dimension x k
  std::vector<Eigen::Index> assignment;  // cluster of each point
  int iterations = 0;                    // centre updates made
  bool converged = false;                // the assignment stopped changing
};

// `points` and `initialCentres` hold one vector per column. Throws InvalidArgumentError for
// mismatched dimensions, no points, no centres or a negative iteration limit.
KMeansResult kMeans(const Eigen::MatrixXd& points, Eigen::MatrixXd initialCentres, int maxIterations = 100);

}  // namespace rgnav
