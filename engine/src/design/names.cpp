// The contract's names of the lighting-design enums (declared in radiant/result.h).
#include "radiant/result.h"

namespace radiant {

const char* to_string(Check::Status status) {
    switch (status) {
        case Check::Status::pass:
            return "pass";
        case Check::Status::fail:
            return "fail";
        case Check::Status::unknown:
            return "unknown";
    }
    return "unknown";
}

const char* to_string(SensorKind kind) {
    switch (kind) {
        case SensorKind::planar:
            return "planar";
        case SensorKind::vertical:
            return "vertical";
        case SensorKind::cylindrical:
            return "cylindrical";
        case SensorKind::semi_cylindrical:
            return "semi-cylindrical";
    }
    return "planar";
}

std::optional<Check::Status> check_status_named(std::string_view name) {
    for (const Check::Status s : {Check::Status::pass, Check::Status::fail, Check::Status::unknown})
        if (name == to_string(s)) return s;
    return std::nullopt;
}

std::optional<SensorKind> sensor_kind_named(std::string_view name) {
    for (const SensorKind k : {SensorKind::planar, SensorKind::vertical, SensorKind::cylindrical,
                               SensorKind::semi_cylindrical})
        if (name == to_string(k)) return k;
    return std::nullopt;
}

}  // namespace radiant
