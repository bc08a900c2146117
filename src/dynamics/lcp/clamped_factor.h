// Cholesky factor L Lᵀ = A_CC of the clamped set C of the pivoting solver, updated as variables
// enter (a row appended: O(k²)) and leave (rows shifted and a rank-1 update: O(k²)) instead of a
// refactorisation per pivot (O(k³)).
//
// The factor doubles as the rank test that keeps redundant contacts out of C (Baraff 1994: four
// coplanar points with one normal make A singular). Appending variable j computes
//   y = L⁻¹ A_Cj,   s_j = A_jj − yᵀy,
// and s_j is the Schur complement of A_CC in A_{C+j,C+j}. With A = J M⁻¹ Jᵀ it equals the squared
// M⁻¹-norm of the part of row J_j orthogonal to the rows of C: zero exactly when contact j is a
// linear combination of the clamped contacts. A variable with s_j ≤ tol·A_jj is refused, so A_CC stays
// positive definite with every pivot bounded below, and no singular system is ever solved.
#pragma once

#include <Eigen/Dense>

#include <vector>

namespace tumble::lcp {

class ClampedFactor {
public:
  void reset(int capacity);
  int size() const { return static_cast<int>(members_.size()); }
  const std::vector<int>& members() const { return members_; }

  // y = L⁻¹ A_Cj in the first size() entries of y (y must hold at least the capacity: the solver
  // pivots thousands of times a step, and a vector resized to each new size is a heap allocation
  // each time); returns the Schur complement s_j = A_jj − yᵀy (≥ 0 up to rounding).
  double schur(const Eigen::MatrixXd& A, int j, Eigen::VectorXd& y) const;
  // Appends j if s_j > rel_tol·A_jj; returns false (and leaves the factor as it was) otherwise.
  bool add(const Eigen::MatrixXd& A, int j, double rel_tol);
  // Removes the member at the given position in members().
  void remove(int position);
  // Solves A_CC x = rhs in place (rhs in the order of members()).
  void solveInPlace(Eigen::Ref<Eigen::VectorXd> rhs) const;
  // Given y = L⁻¹ A_Cd from schur(), returns x = −A_CC⁻¹ A_Cd = −L⁻ᵀ y (in y's first size() entries).
  void backSolve(Eigen::VectorXd& y) const;

private:
  Eigen::MatrixXd L_;  // capacity × capacity; the top-left size()×size() lower triangle is valid
  std::vector<int> members_;
  Eigen::VectorXd y_, x_;   // capacity each: add()'s y and remove()'s rank-1 column
};

}  // namespace tumble::lcp
