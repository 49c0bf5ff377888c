// radiant::Scene → radiant-scene/1 text, so that a scene radiant-bench generates can be solved
// with `radiant solve`, kept as an example or converted for another renderer.
#pragma once

#include <string>

#include "radiant/photometry.h"
#include "radiant/scene.h"

namespace radiant::bench {

/// `scene` as a radiant-scene/1 document that proto::parse_scene reads back to the same scene:
/// photometric tables inline as IES text (ies_text), work-plane sensor sets as their rule (the
/// parser expands it to the same points), other sensor sets as points. Objects are indented, a
/// vertex or face stays on one line. Pure; thread-safe.
std::string scene_document(const Scene& scene);

/// `table` as IES LM-63-2002 text with absolute photometry (lumens per lamp −1, multiplier 1),
/// TILT=NONE, type C, metres; numbers written so that they read back exactly.
std::string ies_text(const PhotometricTable& table, const std::string& label);

}  // namespace radiant::bench
