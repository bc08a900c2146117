#include "bench/series_style.h"

#include <vector>

namespace tumble::bench {

Family familyOf(const std::string& setting, const std::string& engine) {
  auto starts = [&](const char* prefix) { return setting.rfind(prefix, 0) == 0; };
  if (engine == "tumble") {
    if (setting == "tumble-auto") return Family::TumbleAuto;
    if (starts("tumble-ts")) return Family::TumbleTimeStepping;
    if (starts("tumble-penalty")) return Family::TumblePenalty;
    return Family::TumbleBaraff;
  }
  if (engine == "bullet") return Family::Bullet;
  if (engine == "ode") return Family::Ode;
  if (engine == "mujoco") return Family::Mujoco;
  return Family::Other;
}

SeriesStyle seriesStyle(Family family, int index) {
  // Shades run from dark to light within a hue; each list is long enough for the family's
  // settings in this build and cycles beyond that (the marker still differs).
  static const std::vector<Rgb> kAuto{{0, 0, 0}};
  static const std::vector<Rgb> kBaraff{{178, 24, 43}, {230, 75, 60}, {120, 10, 30}, {244, 130, 120}, {200, 60, 110}};
  static const std::vector<Rgb> kTimeStepping{{230, 120, 0}, {250, 170, 40}, {170, 85, 0}, {200, 150, 90}};
  static const std::vector<Rgb> kPenalty{{0, 128, 128}, {40, 180, 170}, {0, 90, 95}, {100, 200, 190},
                                         {20, 150, 120}, {70, 130, 150}};
  static const std::vector<Rgb> kBullet{{30, 90, 200}, {110, 160, 235}};
  static const std::vector<Rgb> kOde{{40, 140, 50}, {130, 200, 90}};
  static const std::vector<Rgb> kMujoco{{110, 60, 170}, {175, 140, 215}};
  static const std::vector<Rgb> kOther{{110, 110, 110}, {170, 170, 170}};
  const std::vector<Rgb>* shades = &kOther;
  switch (family) {
    case Family::TumbleAuto: shades = &kAuto; break;
    case Family::TumbleBaraff: shades = &kBaraff; break;
    case Family::TumbleTimeStepping: shades = &kTimeStepping; break;
    case Family::TumblePenalty: shades = &kPenalty; break;
    case Family::Bullet: shades = &kBullet; break;
    case Family::Ode: shades = &kOde; break;
    case Family::Mujoco: shades = &kMujoco; break;
    case Family::Other: break;
  }
  constexpr Marker kMarkers[] = {Marker::Circle, Marker::Square, Marker::TriangleUp, Marker::Diamond,
                                 Marker::TriangleDown, Marker::Cross};
  const auto i = static_cast<std::size_t>(index);
  return {(*shades)[i % shades->size()], kMarkers[i % std::size(kMarkers)],
          family == Family::TumbleAuto ? 4.0 : 1.6};
}

}  // namespace tumble::bench
