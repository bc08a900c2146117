#include "random_lcp.h"

namespace tumble::lcp::test {

Eigen::MatrixXd randomPsd(int n, int rank, double shift, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd M(rank, n);
  for (int i = 0; i < rank; ++i)
    for (int j = 0; j < n; ++j) M(i, j) = u(rng);
  Eigen::MatrixXd A = M.transpose() * M + shift * Eigen::MatrixXd::Identity(n, n);
  return 0.5 * (A + A.transpose());
}

Eigen::VectorXd randomVector(int n, double scale, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-scale, scale);
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v[i] = u(rng);
  return v;
}

Eigen::VectorXd solvableRhs(const Eigen::MatrixXd& A, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = static_cast<int>(A.rows());
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n), w = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < n; ++i) (u(rng) < 0.5 ? f[i] : w[i]) = u(rng);
  return w - A * f;
}

}  // namespace tumble::lcp::test
