// A subspace step for an island's impulse problem that Gauss-Seidel leaves unconverged: with the
// rows split by the current answer into those that hold an equality (a normal row that pushes,
// w = 0; a friction row inside its pyramid, w = 0) and those at a bound (a normal row at zero, a
// friction row at +-mu p_n, held at its value), the equalities are solved together by conjugate
// gradients on the sparse A = J M^-1 J^T restricted to them, and the answer is projected back onto
// the bounds. Gauss-Seidel passes a change along a chain of bodies by about one body per sweep,
// and a long chain of heavy bodies under load (a masonry arch: the thrust runs through every stone
// to the feet) converges at about 1 - c / N^2 per sweep: 200 sweeps left a 25-stone arch with
// unbalanced impulses that made it sag 0.35 m in 20 s, and a 101-stone one collapsed. Conjugate
// gradients need about N iterations there. When the split is right the step is the answer, and
// Gauss-Seidel only polishes it and corrects the split (compare the subspace minimisation of
// J. L. Morales, J. Nocedal and M. Smelyanskiy, "An algorithm for the fast solution of symmetric
// linear complementarity problems", Numerische Mathematik, 2008).
//
// The step is kept only if it lowers the merit 1/2 p^T A p + (b - target)^T p, which every
// Gauss-Seidel update lowers too (target: a sliding row's, else 0; for an impact with no targets,
// b = J v and the merit is the change of kinetic energy, so the step adds no energy); otherwise
// shorter steps towards it are tried, and then none. The merit ignores that friction bounds move
// with the normal forces, so the caller also keeps a round only if it leaves Gauss-Seidel nearer
// its fixed point (island_impulses.cpp). Why not a
// direct factorisation: A is singular where contacts are redundant (four coplanar corners of a
// face), and with a regularisation small enough not to bend the chain's softest modes the targets'
// rounding along the null space came back as impulses of 1e9 N s. Conjugate gradients started from
// the current answer do not grow along the null space.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamics/contact_jacobian.h"
#include "dynamics/row_gauss_seidel.h"
#include "dynamics/world.h"

namespace tumble {

// Writes to `out` f with its equality rows re-solved exactly (w = A f + b = 0 on them) and then
// projected onto the bounds of `limits`. `f` is the current answer (Gauss-Seidel's); `out` has one
// entry per row and must not overlap it. Its work and its buffers grow with the island, not with
// the world: a pile of 10 000 boxes has hundreds of islands a step.
void activeSetStep(const World& world, const std::vector<ContactRow>& rows, Eigen::Ref<const Eigen::VectorXd> b,
                   const std::vector<RowLimit>& limits, Eigen::Ref<const Eigen::VectorXd> f,
                   Eigen::Ref<Eigen::VectorXd> out);

}  // namespace tumble
