#include "contact_jacobian.h"

#include <limits>

namespace tumble::lcp::test {

Eigen::MatrixXd ContactSystem::jacobian() const {
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(rows.size(), 6 * bodies.size());
  for (size_t r = 0; r < rows.size(); ++r) {
    const ContactRow& c = rows[r];
    const auto put = [&](int body, double sign) {
      if (body < 0) return;
      const Eigen::Vector3d arm = c.point - bodies[body].com;
      J.block<1, 3>(r, 6 * body) += sign * c.dir.transpose();
      J.block<1, 3>(r, 6 * body + 3) += sign * arm.cross(c.dir).transpose();
    };
    put(c.a, 1.0);
    put(c.b, -1.0);
  }
  return J;
}

Eigen::MatrixXd ContactSystem::inverseMass() const {
  Eigen::MatrixXd Minv = Eigen::MatrixXd::Zero(6 * bodies.size(), 6 * bodies.size());
  for (size_t i = 0; i < bodies.size(); ++i) {
    Minv.block<3, 3>(6 * i, 6 * i) = Eigen::Matrix3d::Identity() / bodies[i].mass;
    Minv.block<3, 3>(6 * i + 3, 6 * i + 3) = bodies[i].inertia.inverse();
  }
  return Minv;
}

Eigen::VectorXd ContactSystem::externalForce() const {
  Eigen::VectorXd F = Eigen::VectorXd::Zero(6 * bodies.size());
  for (size_t i = 0; i < bodies.size(); ++i) F.segment<3>(6 * i) = bodies[i].mass * gravity;
  return F;
}

LcpProblem ContactSystem::problem() const {
  const Eigen::MatrixXd J = jacobian(), Minv = inverseMass();
  const int n = static_cast<int>(rows.size());
  LcpProblem p = LcpProblem::plain(J * Minv * J.transpose(), J * Minv * externalForce());
  p.A = (0.5 * (p.A + p.A.transpose())).eval();  // exactly symmetric
  p.friction_of.assign(n, -1);
  p.mu = Eigen::VectorXd::Zero(n);
  for (int r = 0; r < n; ++r) {
    p.friction_of[r] = rows[r].friction_of;
    p.mu[r] = rows[r].mu;
  }
  return p;
}

Eigen::VectorXd ContactSystem::accelerations(const Eigen::VectorXd& f) const {
  return inverseMass() * (jacobian().transpose() * f + externalForce());
}

std::vector<Eigen::Vector3d> rectangleCorners(double cx, double cy, double hx, double hy, double z) {
  return {{cx - hx, cy - hy, z}, {cx + hx, cy - hy, z}, {cx + hx, cy + hy, z}, {cx - hx, cy + hy, z}};
}

int addNormalContacts(ContactSystem& s, int a, int b, const std::vector<Eigen::Vector3d>& points) {
  const int first = static_cast<int>(s.rows.size());
  for (const auto& p : points) s.rows.push_back({a, b, p, Eigen::Vector3d::UnitZ(), -1, 0});
  return first;
}

void addFrictionRows(ContactSystem& s, double mu) {
  const size_t normals = s.rows.size();
  for (size_t r = 0; r < normals; ++r)
    for (const Eigen::Vector3d& t : {Eigen::Vector3d::UnitX().eval(), Eigen::Vector3d::UnitY().eval()}) {
      ContactRow c = s.rows[r];
      c.dir = t;
      c.friction_of = static_cast<int>(r);
      c.mu = mu;
      s.rows.push_back(c);
    }
}

ContactSystem cubeStack(int n, bool friction, double mu) {
  ContactSystem s;
  for (int i = 0; i < n; ++i) {
    Body body;
    body.com = {0, 0, i + 0.5};
    s.bodies.push_back(body);
    addNormalContacts(s, i, i - 1, rectangleCorners(0, 0, 0.5, 0.5, i));
  }
  if (friction) addFrictionRows(s, mu);
  return s;
}

}  // namespace tumble::lcp::test
