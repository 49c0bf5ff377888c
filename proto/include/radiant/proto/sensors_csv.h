// The sensors of a result as CSV (RFC 4180) for spreadsheets: one row per point with its
// position and normal (metres) and its illuminance (lux).
#pragma once

#include <string>
#include <vector>

#include "radiant/proto/significant_digits.h"
#include "radiant/result.h"

namespace radiant::proto {

/// The header `set,index,x,y,z,nx,ny,nz,lux`, then every point of every set in result order
/// (index counts from 0 within its set). Lines end in CRLF; a set name with a comma, quote or
/// line break is quoted. Lux carry `digits` significant digits, coordinates micrometres — the
/// numbers of the JSON result. A set without points (a result stored before results carried
/// them) adds no rows. Thread-safe.
std::string sensors_csv(const std::vector<SensorResult>& sensors, int digits = kDefaultDigits);

}  // namespace radiant::proto
