// libFuzzer target: a scene document as a client sends it (JSON syntax, budget, structure and
// check_scene), inline OBJ, glTF and IES models included.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "radiant/proto/scene_json.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    // No scene directory: as in the service, file keys are refused rather than read.
    const radiant::proto::ParseOutcome outcome = radiant::proto::parse_scene(text);
    // The contract: a scene exactly when there is no problem.
    if (outcome.scene.has_value() != outcome.problems.empty()) __builtin_trap();
    return 0;
}
