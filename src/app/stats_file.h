// --stats FILE.json: what a run's summary line and -v print, as a file a script can read — where
// the time went (phases and pipeline stages), what the contact pipeline did, and how far the run
// drifted in energy and sank into contacts.
#pragma once

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "dynamics/simulator.h"

namespace tumble {

// Refuses, before any work, a stats file that exists (Error(CantCreate), 73) unless `overwrite`,
// or a name no output may take (a folder, a device).
void checkStatsOutput(const std::filesystem::path& path, bool overwrite);

// The simulation's part: steps, per-stage seconds, counters, energy and penetration extremes.
nlohmann::json simulationStats(const Simulator& simulator, const SimulationPlan& plan, double simulated_s);

// Writes `stats` whole (a temporary sibling renamed onto `path`), as every output is.
void writeStatsFile(const std::filesystem::path& path, bool overwrite, const nlohmann::json& stats);

}  // namespace tumble
