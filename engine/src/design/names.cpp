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

}  // namespace radiant
