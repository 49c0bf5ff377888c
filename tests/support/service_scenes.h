// Tiny scenes for service tests: one that solves in well under a second, one that keeps a worker
// busy until it is cancelled or hits its time limit.
#pragma once

#include <string>

namespace radiant::test {

/// A 1×1×1 m room (reflectance 0.5) with a ceiling panel; tolerance 0.1 keeps it ~100 patches.
inline std::string tiny_room(const char* settings = R"({"tolerance": 0.1})") {
    return std::string(R"({"format": "radiant-scene/1", "name": "tiny-room",
 "materials": {"wall": {"reflectance": 0.5},
               "lamp": {"reflectance": 0.5, "emission": {"flux": 1000}}},
 "surfaces": [
  {"name": "room", "material": "wall", "box": {"min": [0,0,0], "max": [1,1,1], "facing": "in"}},
  {"name": "panel", "material": "lamp",
   "polygon": [[0.25,0.25,0.99],[0.25,0.75,0.99],[0.75,0.75,0.99],[0.75,0.25,0.99]]}],
 "sensors": [{"name": "floor", "points": [[0.5,0.5,0]], "normal": [0,0,1]}],
 "settings": )") +
           settings + "}";
}

/// The tiny room lit by two groups — the panel ("panel") and a downlight ("down") — over a grid
/// of nu × nu floor points, with one light scene: what POST /v1/jobs/{id}/scenes evaluates.
inline std::string grouped_room(int nu = 3) {
    const std::string n = std::to_string(nu);
    return std::string(R"({"format": "radiant-scene/1", "name": "grouped-room",
 "materials": {"wall": {"reflectance": 0.5},
               "lamp": {"reflectance": 0.5, "emission": {"flux": 1000, "group": "panel"}}},
 "surfaces": [
  {"name": "room", "material": "wall", "box": {"min": [0,0,0], "max": [1,1,1], "facing": "in"}},
  {"name": "panel", "material": "lamp",
   "polygon": [[0.25,0.25,0.99],[0.25,0.75,0.99],[0.75,0.75,0.99],[0.75,0.25,0.99]]}],
 "luminaires": [{"name": "D", "position": [0.2, 0.2, 0.95], "flux": 500,
                 "distribution": "lambertian", "group": "down"}],
 "sensors": [{"name": "floor", "normal": [0,0,1],
              "grid": {"origin": [0.05,0.05,0.01], "u": [0.9,0,0], "v": [0,0.9,0], "nu": )") +
           n + R"(, "nv": )" + n + R"(}}],
 "light_scenes": [{"name": "panel only", "dimming": {"panel": 1}}],
 "settings": {"tolerance": 0.1}})";
}

/// The same room meshed finely: it runs until cancelled or for `seconds`.
inline std::string slow_room(int seconds = 20) {
    return tiny_room(
        (R"({"tolerance": 0.001, "max_seconds": )" + std::to_string(seconds) + "}").c_str());
}

}  // namespace radiant::test
