// How far apart two solutions of the same scene are, in the quantities a user reads: the
// sensor sets, or where there are none the surfaces' mean irradiance and radiosity.
#pragma once

#include <vector>

#include "radiant/result.h"

namespace radiant {

/// Values darker than this share of their kind's mean are measured against that share.
inline constexpr double kDarkShare = 0.1;
/// Surfaces smaller than this share of the total area do not count in the surfaces' measure: a
/// chair leg's mean is not what the error bar is about.
inline constexpr double kSmallSurfaceShare = 0.01;

/// Which surfaces count in the surfaces' measure, by their areas: those of at least
/// kSmallSurfaceShare of the total, or every one where none is that large.
std::vector<bool> counted_surfaces(const std::vector<double>& areas_m2);

/// How far `b` is from `a` in the measure the error estimate states (issue 27): for each sensor
/// set, the RMS over its points of the difference relative to the set's mean in `a`, the
/// largest over the sets (a set darker than a tenth of the mean of all sensor points measured
/// against that tenth). A scene without sensors (or whose sensor sets differ in shape) takes
/// instead the RMS of the relative differences of the mean irradiance and the mean radiosity of
/// the counted surfaces (counted_surfaces), each measured against itself in
/// `a`, or against a tenth of the area-weighted mean of its kind where it is darker, so that a
/// sealed dark room does not count as all error.
double relative_rms_difference(const Result& a, const Result& b);

/// The surfaces' part of relative_rms_difference, whether or not there are sensors.
double surface_rms_difference(const Result& a, const Result& b);

/// relative_rms_difference's sensor measure of differences given directly: each set's RMS of
/// `differences` (lux, in a's sets and points) over the set's mean in `a`, the largest; 0 when
/// the sets differ in shape.
double sensor_rms_of(const Result& a, const std::vector<SensorResult>& differences);

}  // namespace radiant
