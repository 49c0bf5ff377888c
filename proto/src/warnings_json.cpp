#include "radiant/proto/warnings_json.h"

namespace radiant::proto {

nlohmann::json warnings_to_json(const std::vector<Warning>& warnings) {
    nlohmann::json out = nlohmann::json::array();
    for (const Warning& w : warnings) {
        out.push_back({{"code", w.code}, {"message", w.message}, {"pointer", w.pointer}});
    }
    return out;
}

std::string message_with_code(const Warning& warning) {
    return warning.message + " [" + warning.code + "]";
}

std::string format_warning(const std::string& file, const Warning& warning) {
    return file + ": " + warning.pointer + ": " + message_with_code(warning);
}

}  // namespace radiant::proto
