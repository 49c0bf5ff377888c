// libFuzzer target: Honeybee models (HBJSON) converted to scene documents (`radiant import`).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "radiant/proto/honeybee.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto outcome =
        radiant::proto::honeybee_to_scene({reinterpret_cast<const char*>(data), size});
    if (outcome.scene.has_value() != outcome.problems.empty()) __builtin_trap();
    return 0;
}
