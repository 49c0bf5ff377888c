// Colour scales of the view and its legend: luminance as grey and illuminance as false colour.
// Colours are linear RGB in [0, 1] (what three.js takes for vertex colours); the legend, drawn
// on a 2D canvas, encodes them with srgbEncode so both show the same pixels.

/// Linear → sRGB transfer (IEC 61966-2-1).
export function srgbEncode(x) {
    const c = Math.min(1, Math.max(0, x));
    return c <= 0.0031308 ? 12.92 * c : 1.055 * c ** (1 / 2.4) - 0.055;
}

export function srgbDecode(x) {
    return x <= 0.04045 ? x / 12.92 : ((x + 0.055) / 1.055) ** 2.4;
}

/// The false-colour stops, in sRGB: blue (dark) → cyan → green → yellow → red (bright).
const FALSE_COLOUR_STOPS = [
    [0.13, 0.19, 0.75],
    [0.0, 0.65, 0.9],
    [0.15, 0.75, 0.25],
    [0.98, 0.88, 0.1],
    [0.88, 0.12, 0.08],
];

/// The false colour of t ∈ [0, 1] as linear RGB.
export function falseColour(t) {
    const x =
        Math.min(1, Math.max(0, Number.isFinite(t) ? t : 0)) * (FALSE_COLOUR_STOPS.length - 1);
    const i = Math.min(Math.floor(x), FALSE_COLOUR_STOPS.length - 2);
    const f = x - i;
    return FALSE_COLOUR_STOPS[i].map((a, k) =>
        srgbDecode(a + (FALSE_COLOUR_STOPS[i + 1][k] - a) * f),
    );
}

/// The grey of t ∈ [0, 1] (linear, so the shading is proportional to luminance).
export function grey(t) {
    const g = Math.min(1, Math.max(0, Number.isFinite(t) ? t : 0));
    return [g, g, g];
}

/// The smallest 1, 1.5, 2, 2.5, 3, 4, 5, 6 or 8 × 10^k at or above `value` (a legend's round
/// top, using most of the scale); 1 for 0.
export function niceCeiling(value) {
    if (!(value > 0) || !Number.isFinite(value)) return 1;
    const power = 10 ** Math.floor(Math.log10(value));
    for (const step of [1, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10]) {
        if (step * power >= value * (1 - 1e-6)) return step * power; // float32 inputs
    }
    return 10 * power;
}

/// `count` + 1 evenly spaced ticks from 0 to `top`.
export function ticks(top, count = 5) {
    return Array.from({ length: count + 1 }, (_, i) => (top * i) / count);
}

/// The value at quantile q (0–1) of `values`, ignoring non-finite ones; 0 when empty.
export function quantile(values, q) {
    const sorted = Array.from(values)
        .filter(Number.isFinite)
        .sort((a, b) => a - b);
    if (!sorted.length) return 0;
    return sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))];
}

/// Luminance of a Lambertian surface from its radiosity: L = B / π (cd/m² from lm/m²).
export const luminanceFromRadiosity = (radiosity) => radiosity / Math.PI;

/// The legend's top for luminance: the 98th percentile rounded up, so a few very bright patches
/// (emitting panels) do not turn the whole room black.
export function luminanceTop(vertexRadiosity) {
    return niceCeiling(luminanceFromRadiosity(quantile(vertexRadiosity, 0.98)));
}

/// A value for a legend: 3 significant digits, no exponent for the usual lux and cd/m².
export function formatValue(value) {
    if (!Number.isFinite(value)) return "–";
    const a = Math.abs(value);
    if (a >= 100 || a === 0) return Math.round(value).toString();
    if (a >= 10) return value.toFixed(1);
    if (a >= 1) return value.toFixed(2);
    return value.toPrecision(2);
}
