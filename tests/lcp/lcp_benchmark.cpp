// Not a test (numbers are measured by benchmarks, never by timed tests): µs per solve of
// solveDantzig against solvePgs on stack-of-cubes problems (4 corner contacts per interface; with
// friction 2 signed tangents per contact) and on a random 400-variable PD problem; on the friction
// problems also Lemke's method, the fallback where the direct solver's friction passes do not
// settle (lemke_friction.h). CSV on stdout.
#include "contact_jacobian.h"
#include "dynamics/lcp/dantzig_solver.h"
#include "dynamics/lcp/lemke_friction.h"
#include "dynamics/lcp/pgs_solver.h"
#include "random_lcp.h"

#include <chrono>
#include <cstdio>
#include <functional>

using namespace tumble::lcp;
using namespace tumble::lcp::test;

namespace {

// Repeats solve until 0.3 s have passed (at least 3 times); returns µs per call and the last result.
double timeSolve(const std::function<LcpResult()>& solve, LcpResult& last) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  int calls = 0;
  double elapsed = 0;
  do {
    last = solve();
    ++calls;
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  } while (elapsed < 0.3 || calls < 3);
  return 1e6 * elapsed / calls;
}

void report(const char* name, const LcpProblem& p) {
  PgsSettings pgs;  // documented defaults
  LcpResult d, g;
  const double td = timeSolve([&] { return solveDantzig(p); }, d);
  const double tg = timeSolve([&] { return solvePgs(p, pgs); }, g);
  std::printf("%s,%d,dantzig,%.1f,%d,%d,%s,%.3g\n", name, p.size(), td, d.iterations,
              d.friction_passes, toString(d.status), d.residual.complementarity);
  std::printf("%s,%d,pgs,%.1f,%d,0,%s,%.3g\n", name, p.size(), tg, g.iterations, toString(g.status),
              g.residual.complementarity);
  if (!lemkeCovers(p) || p.friction_of.empty()) return;
  LcpResult l;
  const double tl = timeSolve(
      [&] {
        LcpResult r;
        solveLemkeFriction(p, LemkeSettings{}, r);
        return r;
      },
      l);
  std::printf("%s,%d,lemke,%.1f,%d,0,%s,%.3g\n", name, p.size(), tl, l.iterations, toString(l.status),
              l.residual.complementarity);
}

}  // namespace

int main() {
  std::printf("problem,n,solver,us_per_solve,pivots_or_sweeps,friction_passes,status,"
              "complementarity_residual\n");
  report("stack10", cubeStack(10, false).problem());
  report("stack2_friction", cubeStack(2, true, 0.5).problem());
  report("stack4_friction", cubeStack(4, true, 0.5).problem());
  report("stack8_friction", cubeStack(8, true, 0.5).problem());
  report("stack10_friction", cubeStack(10, true, 0.5).problem());
  report("stack100", cubeStack(100, false).problem());
  report("stack34_friction", cubeStack(34, true, 0.5).problem());
  std::mt19937 rng(400);
  report("random_pd", LcpProblem::plain(randomPsd(400, 400, 0.1, rng), randomVector(400, 1.0, rng)));
  return 0;
}
