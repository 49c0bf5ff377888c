// `radiant plan SCENE.json --out plan.png [--sensors NAME]`: solve, then a top-down false-colour
// map of a sensor set's illuminance with its metrics (Ē, E_min, E_max, U₀, U_d) and a legend.
#pragma once

#include <CLI/CLI.hpp>

namespace radiant::cli {

void add_plan_command(CLI::App& app, int& exit_code);

}  // namespace radiant::cli
