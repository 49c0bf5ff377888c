// How far apart two solutions of the same scene are, in the quantities a user reads: the
// surfaces' mean irradiance and radiosity and every sensor value.
#pragma once

#include "radiant/result.h"

namespace radiant {

/// The largest relative difference between `a` and `b` (solutions of one scene, so their
/// surfaces and sensors correspond by index), over every sensor value and the means of the
/// surfaces that make up at least 1 % of the scene's area. A value is measured against itself
/// in `a`, or against a tenth of the mean of its kind where it is darker, so that a sealed dark
/// room does not count as all error.
double largest_relative_difference(const Result& a, const Result& b);

/// How far `b` is from `a` in the measure the error estimate states (issue 27): for each sensor
/// set, the RMS over its points of the difference relative to the set's mean in `a`, the
/// largest over the sets (a set darker than a tenth of the mean of all sensor points measured
/// against that tenth). A scene without sensors (or whose sensor sets differ in shape) takes
/// instead the RMS of the relative differences of the mean irradiance and the mean radiosity of
/// the surfaces that count in largest_relative_difference, each measured as there.
double relative_rms_difference(const Result& a, const Result& b);

}  // namespace radiant
