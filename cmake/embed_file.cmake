# Writes INPUT's bytes as a C++ source defining `std::string_view NAME()` (in namespace
# radiant), so a binary carries a file it serves without looking for it on disk. A byte array,
# not a string literal: literals have length limits, arrays do not.
# Usage: cmake -DINPUT=file -DOUTPUT=file.cpp -DNAME=function -P embed_file.cmake
file(READ "${INPUT}" hex HEX)
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "'\\\\x\\1'," bytes "${hex}")
string(REGEX REPLACE "(([^,]*,){16})" "\\1\n    " bytes "${bytes}")
get_filename_component(source "${INPUT}" NAME)
file(WRITE "${OUTPUT}.tmp" "// Generated from ${source} by cmake/embed_file.cmake; do not edit.
#include <string_view>

namespace radiant {
namespace {
constexpr char kBytes[] = {
    ${bytes}'\\0'};
}  // namespace

std::string_view ${NAME}() { return {kBytes, sizeof kBytes - 1}; }

}  // namespace radiant
")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
