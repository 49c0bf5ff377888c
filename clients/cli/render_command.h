// `radiant render SCENE.json --out view.png [camera] [--falsecolor]`: solve, then a perspective
// picture of the solved room — tone-mapped luminance, or a false-colour lux map with a legend.
#pragma once

#include <CLI/CLI.hpp>

namespace radiant::cli {

void add_render_command(CLI::App& app, int& exit_code);

}  // namespace radiant::cli
