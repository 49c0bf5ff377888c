#include "radiant/scene.h"

namespace radiant {

double meters_per_unit(LengthUnit unit) {
    switch (unit) {
        case LengthUnit::m:
            return 1.0;
        case LengthUnit::cm:
            return 0.01;
        case LengthUnit::mm:
            return 0.001;
        case LengthUnit::ft:
            return 0.3048;
        case LengthUnit::in:
            return 0.0254;
    }
    return 1.0;
}

}  // namespace radiant
