#include "dynamics/joints/joint_mobility.h"

#include <Eigen/Dense>

#include "dynamics/joints/contact_joint_lcp.h"
#include "dynamics/joints/joint_rows.h"

namespace tumble {

Eigen::MatrixXd constrainedDelassus(const World& world, const std::vector<ContactRow>& rows, const Eigen::MatrixXd& free) {
  std::vector<JointRow> all;
  for (const ContactRow& row : rows) all.push_back(asGenericRow(row));
  std::vector<JointRow> joints;
  buildJointRows(world, RowChoice{}, joints);
  if (joints.empty()) return free;
  all.insert(all.end(), joints.begin(), joints.end());
  const int nc = static_cast<int>(rows.size()), nj = static_cast<int>(joints.size());
  const Eigen::MatrixXd A = jointDelassus(world, all);
  const Eigen::MatrixXd B = A.block(0, nc, nc, nj);   // J_c M^-1 J_j^T
  // The pseudo-inverse's solve: redundant joint rows (a closed loop) do not make it singular.
  const Eigen::MatrixXd reaction = Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(A.block(nc, nc, nj, nj)).solve(B.transpose());
  return free - B * reaction;
}

}  // namespace tumble
