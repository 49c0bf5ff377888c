// libFuzzer target: Wavefront OBJ with inline MTL, as a scene's "obj" and "mtl" keys give them.
// The input is the OBJ text, then optionally a NUL byte and the MTL text.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "import/obj_import.h"
#include "imported_geometry_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    const std::size_t nul = input.find('\0');
    radiant::proto::MtlSource mtl;
    if (nul != std::string_view::npos) mtl.text = std::string(input.substr(nul + 1));
    const auto outcome =
        radiant::proto::import_obj(std::string(input.substr(0, nul)), mtl, radiant::fuzz::kBudget);
    radiant::fuzz::check_geometry(outcome);
    return 0;
}
