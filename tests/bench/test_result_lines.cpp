#include <catch2/catch.hpp>
#include <cmath>

#include "bench/job_process.h"

using namespace tumble::bench;

TEST_CASE("a result survives the trip from the child process") {
  RunResult r;
  r.scene = "S6_100";
  r.setting = "bullet-nosleep";
  r.engine = "bullet";
  r.dt = 1.0 / 240;
  r.wall_per_sim = 0.0849;
  r.reps = 3;
  r.simulated_s = 5;
  r.cut = true;
  r.peak_rss_mb = 14.5;
  r.metrics = {{"max_pen_end", 3.9e-4}, {"escaped", 0}, {"sc_err", std::nan("")}};
  r.note = "cut at 1.2 s\tof 5";
  const RunResult back = decodeResult(encodeResult(r));
  CHECK(back.scene == r.scene);
  CHECK(back.setting == r.setting);
  CHECK(back.dt == r.dt);
  CHECK(back.wall_per_sim == r.wall_per_sim);
  CHECK(back.cut);
  CHECK(back.peak_rss_mb == 14.5);
  REQUIRE(back.metrics.size() == 3);
  CHECK(back.metrics[0].value == 3.9e-4);
  CHECK(std::isnan(back.metrics[2].value));
  CHECK(back.note == "cut at 1.2 s of 5");
}
