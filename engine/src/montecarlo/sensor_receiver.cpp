#include "montecarlo/sensor_receiver.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace radiant {

double SensorReceiver::weight(const Vec3& w) const {
    constexpr double kPi = std::numbers::pi;
    switch (kind_) {
        case SensorKind::planar:
        case SensorKind::vertical:
            return std::max(0.0, dot(normal_, w));
        case SensorKind::cylindrical:
            return std::hypot(w.x, w.y) / kPi;
        case SensorKind::semi_cylindrical:
            return (std::hypot(w.x, w.y) + normal_.x * w.x + normal_.y * w.y) / kPi;
    }
    return 0;
}

Vec3 SensorReceiver::normal_at(double u) const {
    constexpr double kPi = std::numbers::pi;
    switch (kind_) {
        case SensorKind::planar:
        case SensorKind::vertical:
            return normal_;
        case SensorKind::cylindrical:
            return {std::cos(2 * kPi * u), std::sin(2 * kPi * u), 0};
        case SensorKind::semi_cylindrical: {
            // The half of the horizontal normals within 90° of the facing.
            const double psi = kPi * (u - 0.5), c = std::cos(psi), s = std::sin(psi);
            return {normal_.x * c - normal_.y * s, normal_.x * s + normal_.y * c, 0};
        }
    }
    return normal_;
}

}  // namespace radiant
