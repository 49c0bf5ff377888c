// Files the daemon serves from its own bytes (cmake/embed_file.cmake), so an installed radiantd
// needs nothing beside it to describe itself.
#pragma once

#include <string_view>

namespace radiant {

/// proto/openapi.yaml as it was when radiantd was built.
std::string_view openapi_yaml();

}  // namespace radiant
