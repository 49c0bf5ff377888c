// libFuzzer target: IES LM-63 photometric files.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "photometric_table_check.h"
#include "photometry/ies_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto table = radiant::proto::read_ies({reinterpret_cast<const char*>(data), size});
    radiant::fuzz::check_table(table);
    return 0;
}
