// How many digits the numbers of a result carry: a value solved to 1 % does not deserve 16
// significant digits, and a reader (or a spreadsheet) should not have to wade through them.
#pragma once

namespace radiant::proto {

/// Significant digits of a result's values unless settings.digits or `--digits` asks otherwise.
inline constexpr int kDefaultDigits = 4;
/// 17 significant digits read back as the same double: values are then written unrounded.
inline constexpr int kMaxDigits = 17;
/// Error estimates are estimates: 3 significant digits, rounded up so that they stay bounds.
inline constexpr int kEstimateDigits = 3;
/// Lengths (points, normals, mesh vertices) are rounded to micrometres, whatever their size.
inline constexpr int kLengthDecimals = 6;

/// `value` rounded to the nearest number with `digits` significant digits (1–17; 17 and more
/// leave it as it is). Non-finite values are returned unchanged; −0 becomes 0.
double round_significant(double value, int digits);

/// `value` rounded away from zero to `digits` significant digits, so that a bound stays one.
double round_up_significant(double value, int digits);

/// `value` rounded to the nearest multiple of 10^−decimals.
double round_decimals(double value, int decimals);

}  // namespace radiant::proto
