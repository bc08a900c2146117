// Contact rows: the one place where a contact becomes rows of the Jacobian, for every solver of
// both contact models (Box2D v3's contact solver has the same single home for prepare, warm
// start and store). A contact's rows are its normal row, then its friction rows: two tangents (a
// friction pyramid, tangentsOf) where it has friction, or one row against its slide. A force f
// along a row pushes B by +f dir and A by -f dir (contact_jacobian.h).
//
// Also here: the LCP over a set of contacts (A = J M^-1 J^T, tangent rows bounded by +-mu times
// their contact's normal variable, ODE's findex convention), its pivoting solve and the test of
// whether a pivoting answer that stopped short is usable; warm starts from the impulse memory and
// the impulses stored back into it.
#pragma once

#include <span>
#include <utility>
#include <vector>

#include "dynamics/contact.h"
#include "dynamics/contact_jacobian.h"
#include "dynamics/contact_solve_common.h"
#include "dynamics/impulse_memory.h"
#include "dynamics/lcp/lcp_problem.h"
#include "dynamics/row_gauss_seidel.h"
#include "dynamics/world.h"

namespace tumble {

struct ContactRows {
  std::vector<ContactRow> rows;
  std::vector<int> normal_row;   // per contact: its normal row; its friction rows follow it

  // Appends contact c's normal row, then two tangent rows if `friction` and c has mu > 0.
  void addContact(const World& world, const Contact& c, bool friction);
  // Appends contact c's normal row, then one friction row along `against` (a unit vector
  // against its slide).
  void addSlidingContact(const World& world, const Contact& c, const Eigen::Vector3d& against);
  // The rows [first, end) of contact k.
  std::pair<int, int> rowsOf(std::size_t k) const;
  int size() const { return static_cast<int>(rows.size()); }
};

// The friction row of contact c along `against` (a unit vector against its slide).
ContactRow slideRow(const World& world, const Contact& c, const Eigen::Vector3d& against);

// Every contact of `set` with its friction pyramid (where mu > 0).
ContactRows buildContactRows(const World& world, std::span<const Contact* const> set);
// The same into `out`, whose buffers are reused (a step builds an island's rows every step).
void buildContactRows(const World& world, std::span<const Contact* const> set, ContactRows& out);

// Row limits for Gauss-Seidel: normal rows push, tangent rows stay inside mu times their normal.
// `rows` must hold pyramid rows only (built by addContact).
std::vector<RowLimit> pyramidLimits(const ContactRows& rows, std::span<const Contact* const> set);
void pyramidLimits(const ContactRows& rows, std::span<const Contact* const> set, std::vector<RowLimit>& out);

// The first guess of an impulse solve: last step's impulse of each contact (`last[k]`, null for a
// new contact) projected on its rows, the normal part never pulling.
Eigen::VectorXd warmStart(const ContactRows& rows, std::span<const ImpulseRecord* const> last);
// The same into `out` (one entry per row).
void warmStart(const ContactRows& rows, std::span<const ImpulseRecord* const> last, Eigen::Ref<Eigen::VectorXd> out);

// Per contact, the sum over its rows of f[r] * scale along the row (N s on B, world axes, for
// impulses; scale turns forces over a step into impulses).
std::vector<Eigen::Vector3d> impulsePerContact(const ContactRows& rows, const Eigen::VectorXd& f, double scale);
// The same for contact k alone.
Eigen::Vector3d impulseOfContact(const ContactRows& rows, Eigen::Ref<const Eigen::VectorXd> f, std::size_t k,
                                 double scale);

// A record of the impulse contact c took, for the next step's warm start.
ImpulseRecord impulseRecord(const World& world, const Contact& c, const Eigen::Vector3d& impulse);

struct ContactLcp : ContactRows {
  lcp::LcpProblem problem;       // A = J M^-1 J^T, b = 0, bounds set; the caller fills b
};

// `friction[i]` says whether contact i gets friction rows (and it gets them only if mu > 0).
ContactLcp buildContactLcp(const World& world, std::span<const Contact* const> set,
                           const std::vector<char>& friction);
// The same into `out`, every contact with friction (where mu > 0), reusing its storage: an island
// of the size of the last allocates nothing.
void buildContactLcp(const World& world, std::span<const Contact* const> set, ContactLcp& out);

// Solves with the Dantzig pivoting solver at the settings contacts need; counts pivots and failures.
lcp::LcpResult solveContactLcp(const lcp::LcpProblem& p, ContactSolveStats& stats);
void solveContactLcp(const lcp::LcpProblem& p, ContactSolveStats& stats, lcp::LcpResult& r);

// A pivoting answer is usable when solved, or when it stopped short (pivot or friction-pass cap)
// with finite forces that satisfy complementarity to within 1e-6 of the problem's scale.
bool usableLcpAnswer(const lcp::LcpResult& r, const lcp::LcpProblem& p);

// Pivoting costs the cube of the rows: an island of more than max_direct_rows rows (three per
// contact at most) is solved iteratively instead.
inline bool tooLargeToPivot(std::size_t contacts, int max_direct_rows) {
  return 3 * contacts > static_cast<std::size_t>(max_direct_rows);
}

// Relative normal velocity of a contact (m/s, < 0 approaching).
double normalVelocity(const World& world, const Contact& c);
// The same with each body's angular velocity given (body_extent.h, bodySpins).
double normalVelocity(const World& world, const Contact& c, const std::vector<Eigen::Vector3d>& spin);

}  // namespace tumble
