// log(sum(exp(x))) without overflow or underflow, the basis of the log-space HMM recursions
// (Rabiner 1989, section V.A scales instead; log space needs no scale factors). An empty input
// or one of only -inf gives -inf.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <limits>

namespace rgnav {

template <typename Derived>
double logSumExp(const Eigen::DenseBase<Derived>& x) {
  if (x.size() == 0) return -std::numeric_limits<double>::infinity();
  const double top = x.maxCoeff();
  if (top == -std::numeric_limits<double>::infinity()) return top;
  return top + std::log((x.derived().array() - top).exp().sum());
}

}  // namespace rgnav
