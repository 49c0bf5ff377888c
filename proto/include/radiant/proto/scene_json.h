// radiant-scene/1 JSON → radiant::Scene, with every problem reported as a JSON pointer.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "radiant/proto/json_budget.h"
#include "radiant/scene.h"

namespace radiant::proto {

struct ParseLimits {
    std::size_t max_bytes = 64u << 20;  ///< larger documents are refused before parsing
    JsonBudget json;                    ///< refused while parsing, before the DOM is complete
    SceneLimits scene;                  ///< totals, refused before anything is expanded
    /// Polygons, mesh faces and box sides of the whole scene, imported models included.
    std::size_t max_faces = 4000000;
};

/// Problem lists stop at this many, and a last problem (pointer "") counts the rest: a hostile
/// document with millions of bad values must not cost a message for each.
constexpr std::size_t kMaxListedProblems = 100;

/// What a refusal is about, so a service can answer with the fitting status.
enum class Refusal {
    none,
    not_json,     ///< syntax, invalid UTF-8, a duplicate key, a number that overflows
    over_budget,  ///< JSON over ParseLimits::max_bytes or ParseLimits::json
    scene,        ///< a JSON document that is not a valid scene (scene limits included)
};

struct ParseOutcome {
    std::optional<Scene> scene;     ///< set only when `problems` is empty
    std::vector<Problem> problems;  ///< in document order: structure first, then check_scene
    Refusal refusal = Refusal::none;
    bool ok() const { return problems.empty(); }
};

/// Parses and checks a scene document: JSON syntax, structure (types, required and unknown
/// keys), then radiant::check_scene. Reports all problems found, each with the RFC 6901 pointer
/// of the offending value ("" for the whole document). Never throws for bad input. Thread-safe.
/// Model files (`obj_file`, `gltf_file`) are read relative to `scene_directory`; without one
/// they are refused, so a service never reads local files on a client's behalf.
ParseOutcome parse_scene(std::string_view json_text, const ParseLimits& limits = {},
                         const std::optional<std::filesystem::path>& scene_directory = {});

/// Reads and parses a scene file. Files over `limits.max_bytes` are refused without being read;
/// an unreadable file gives one problem with pointer "".
ParseOutcome load_scene_file(const std::filesystem::path& path, const ParseLimits& limits = {});

/// "FILE: /json/pointer: message" (the contract's one-line form; the pointer may be empty).
std::string format_problem(const std::string& file, const Problem& problem);

}  // namespace radiant::proto
