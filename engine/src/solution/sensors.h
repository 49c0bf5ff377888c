// Sensor illuminance by final gather: direct light from luminaires (exact, shadow ray) and from
// every patch (exact point-to-polygon factor × sampled visibility), which covers area emitters
// and reflected light alike. No interpolation over the mesh is involved.
#pragma once

#include <vector>

#include "formfactor/transport.h"
#include "radiant/result.h"

namespace radiant {

// Sampled visibility may leave a sensor this share of tolerance × its illuminance as standard
// deviation (see SampledViews).
constexpr double kSensorNoiseShare = 0.25;

/// Illuminance (lux; luminance of the RGB irradiance for colour scenes) at every sensor point,
/// given per-channel patch radiosity, with sampled visibility's standard deviation held to
/// `noise_share` × each point's illuminance. Parallel over points; deterministic.
std::vector<SensorResult> gather_sensors(const PreparedScene& scene, const Transport& transport,
                                         const std::array<std::vector<double>, 3>& radiosity,
                                         int channels, double noise_share, std::uint64_t& rays);

/// The result of one sensor set before its values: its name, points (world frame, metres) and
/// normal, and for a work plane its grid.
SensorResult sensor_result_for(const PreparedSensorSet& set, const Vec3& world_origin);

/// min, max, average, uniformity = U₀ (min/average) and U_d (min/max) of a set's values.
void fill_sensor_statistics(SensorResult& result);

}  // namespace radiant
