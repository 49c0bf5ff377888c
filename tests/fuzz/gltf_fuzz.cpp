// libFuzzer target: glTF models (.glb, or .gltf JSON with embedded buffers), as a scene's "gltf"
// key gives them once decoded from base64.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "import/gltf_import.h"
#include "imported_geometry_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::vector<unsigned char> bytes(data, data + size);
    // No directory: as in the service, external buffers are refused rather than read.
    const auto outcome = radiant::proto::import_gltf(bytes, radiant::LengthUnit::mm, std::nullopt,
                                                     radiant::fuzz::kBudget);
    radiant::fuzz::check_geometry(outcome);
    return 0;
}
