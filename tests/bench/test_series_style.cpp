// The plots' colours say the contact method: family from the setting's name, shade within it.
#include <catch2/catch.hpp>
#include <set>

#include "bench/series_style.h"

using namespace tumble::bench;

TEST_CASE("each setting falls in its family by name or engine") {
  CHECK(familyOf("tumble-auto", "tumble") == Family::TumbleAuto);
  for (const char* s : {"tumble-rk4", "tumble-rk4-gs", "tumble-rk4-tol1e-4", "tumble-semi", "tumble-semi-tol1e-4"})
    CHECK(familyOf(s, "tumble") == Family::TumbleBaraff);
  for (const char* s : {"tumble-ts", "tumble-ts-gs", "tumble-ts-gs10", "tumble-ts-gs10-sleep"})
    CHECK(familyOf(s, "tumble") == Family::TumbleTimeStepping);
  CHECK(familyOf("tumble-penalty-hc", "tumble") == Family::TumblePenalty);
  CHECK(familyOf("bullet-nosleep", "bullet") == Family::Bullet);
  CHECK(familyOf("ode-quick", "ode") == Family::Ode);
  CHECK(familyOf("mujoco-cg", "mujoco") == Family::Mujoco);
  CHECK(familyOf("physx", "physx") == Family::Other);
}

TEST_CASE("family colours: auto black, Baraff red, time stepping orange, penalty teal") {
  CHECK(seriesStyle(Family::TumbleAuto, 0).colour == Rgb{0, 0, 0});
  for (int i = 0; i < 5; ++i) {
    const Rgb red = seriesStyle(Family::TumbleBaraff, i).colour;
    CHECK(red[0] > red[1] + 60);   // red dominates
    CHECK(red[0] > red[2] + 30);
    const Rgb orange = seriesStyle(Family::TumbleTimeStepping, i).colour;
    CHECK(orange[0] > orange[1]);  // red over green over blue
    CHECK(orange[1] > orange[2] + 30);
  }
  for (int i = 0; i < 6; ++i) {
    const Rgb teal = seriesStyle(Family::TumblePenalty, i).colour;
    CHECK(teal[1] > teal[0] + 40);  // green and blue over red
    CHECK(teal[2] > teal[0] + 40);
  }
}

TEST_CASE("settings of one family look different from each other") {
  for (auto [family, count] : {std::pair{Family::TumbleBaraff, 5}, {Family::TumbleTimeStepping, 4},
                               {Family::TumblePenalty, 6}, {Family::Bullet, 2}}) {
    std::set<std::pair<Rgb, int>> seen;
    for (int i = 0; i < count; ++i) {
      const SeriesStyle s = seriesStyle(family, i);
      seen.insert({s.colour, static_cast<int>(s.marker)});
    }
    CHECK(seen.size() == static_cast<std::size_t>(count));
  }
}
