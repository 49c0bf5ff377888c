// How much a JSON text may ask of the parser. Checked while the text is read, so a hostile
// document is refused at the value that crosses a limit, before the rest is read or built.
#pragma once

#include <cstddef>

namespace radiant::proto {

struct JsonBudget {
    /// Nesting of arrays and objects. Scene documents need 6 levels and Honeybee models about 10;
    /// the bound keeps every recursive walk over a document (ours, tinygltf's) off the stack's end.
    std::size_t max_depth = 64;
    /// Values of every kind. 2²⁴ fits the densest scene a 64 MiB body holds (a mesh's vertices
    /// and faces); each value costs 16 bytes or more once parsed.
    std::size_t max_values = std::size_t{1} << 24;
    /// Arrays and objects: each costs a heap block beside its slot (about 60 bytes), so "[],"
    /// repeated would cost 20 times its size without this bound. 2²² covers 2 million vertices
    /// and 2 million faces written as arrays.
    std::size_t max_containers = std::size_t{1} << 22;
    /// Object members of the whole document: each costs a key string and a slot (about 50 bytes).
    std::size_t max_keys = std::size_t{1} << 21;
};

}  // namespace radiant::proto
