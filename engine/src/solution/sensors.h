// Sensor illuminance by final gather: direct light from luminaires (exact, shadow ray) and from
// every patch (exact point-to-polygon factor × sampled visibility), which covers area emitters
// and reflected light alike. No interpolation over the mesh is involved.
#pragma once

#include <vector>

#include "formfactor/transport.h"
#include "radiant/result.h"

namespace radiant {

/// Illuminance (lux; luminance of the RGB irradiance for colour scenes) at every sensor point,
/// given per-channel patch radiosity. Parallel over points; deterministic.
std::vector<SensorResult> gather_sensors(const PreparedScene& scene, const Transport& transport,
                                         const std::array<std::vector<double>, 3>& radiosity,
                                         int channels, std::uint64_t& rays);

/// min, max, average and uniformity (min/average) of a sensor set's values.
void fill_sensor_statistics(SensorResult& result);

}  // namespace radiant
