// A warm step allocates nothing: once a scene's contacts, rows and islands have been seen, the
// time-stepping model's step reuses every buffer it has. A heap allocation per step is a lock
// and a page fault away from costing as much as a small island's solve, and a pile takes
// hundreds of thousands of steps.
//
// The count is taken by interposing the C allocator (malloc and its kin, which operator new and
// Eigen's dynamic matrices both end in) around glibc's own entry points, so it sees every
// allocation of the process while counting is on. Its own executable: the interposition is
// process-wide, and sanitizer builds, which interpose the allocator themselves, leave it out.
#include <catch2/catch.hpp>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "dynamics/pipeline.h"
#include "scene/scene_loader.h"
#include "scene/world_builder.h"

extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* __libc_memalign(std::size_t, std::size_t);
void __libc_free(void*);
}

namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
void count() {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
}
}  // namespace

extern "C" {
void* malloc(std::size_t n) {
  count();
  return __libc_malloc(n);
}
void* calloc(std::size_t n, std::size_t size) {
  count();
  return __libc_calloc(n, size);
}
void* realloc(void* p, std::size_t n) {
  count();
  return __libc_realloc(p, n);
}
void free(void* p) { __libc_free(p); }
void* memalign(std::size_t alignment, std::size_t n) {
  count();
  return __libc_memalign(alignment, n);
}
void* aligned_alloc(std::size_t alignment, std::size_t n) {
  count();
  return __libc_memalign(alignment, n);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t n) {
  count();
  *out = __libc_memalign(alignment, n);
  return *out ? 0 : 12;   // ENOMEM
}
}

using namespace tumble;

namespace {

// Steps scenes/NAME.json with the time-stepping model for `warm_s`, then counts the allocations
// of the next `counted_s`.
long allocationsAfterWarmUp(const std::string& name, double warm_s, double counted_s, int threads = 1) {
  Scene scene = loadScene(std::string(TUMBLE_SOURCE_DIR) + "/scenes/" + name + ".json");
  scene.simulation.step.model = ContactModel::TimeStepping;
  scene.simulation.step.sleep.enabled = false;   // every island solved at every step
  scene.simulation.step.threads = threads;
  BuiltWorld built = buildWorld(scene);
  Pipeline pipeline(built.world, built.step);
  const long warm = std::lround(warm_s / built.step.dt), counted = std::lround(counted_s / built.step.dt);
  long steps = 0;
  auto step = [&] {
    pipeline.step(built.world, built.step);
    built.world.time = static_cast<double>(++steps) * built.step.dt;
  };
  for (long i = 0; i < warm; ++i) step();
  allocations = 0;
  counting = true;
  for (long i = 0; i < counted; ++i) step();
  counting = false;
  std::printf("%s, time stepping, %d thread(s): %ld allocations in %ld steps after %ld warm-up steps\n",
              name.c_str(), threads, allocations.load(), counted, warm);
  return allocations;
}

}  // namespace

TEST_CASE("the interposed allocator counts what it is meant to", "[allocations]") {
  allocations = 0;
  counting = true;
  std::string* s = new std::string(100, 'x');   // operator new, and the string's buffer
  Eigen::VectorXd v = Eigen::VectorXd::Zero(1000);
  counting = false;
  CHECK(allocations >= 3);
  delete s;
  CHECK(v.size() == 1000);
}

// The stack's island is small enough to pivot, and on about one step in six of the counted second
// Gauss-Seidel leaves it unconverged, so the pivoting solve runs (contact rows, the dense problem,
// the pivoting engine, the friction passes). The pile's islands are all solved by Gauss-Seidel,
// with subspace steps where it stops unconverged.
TEST_CASE("a warm time-stepping step allocates nothing: a stack of ten at rest, pivoted", "[allocations]") {
  CHECK(allocationsAfterWarmUp("stack10", 1.0, 1.0) == 0);
}

TEST_CASE("a warm time-stepping step allocates nothing: the pile of 100 settled in its bin", "[allocations]") {
  CHECK(allocationsAfterWarmUp("pile_time_stepping", 4.0, 1.0) == 0);
}

TEST_CASE("a warm time-stepping step allocates nothing on two threads", "[allocations]") {
  CHECK(allocationsAfterWarmUp("pile_time_stepping", 4.0, 1.0, 2) == 0);
}
