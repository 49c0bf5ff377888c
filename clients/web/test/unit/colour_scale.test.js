import { test } from "node:test";
import assert from "node:assert/strict";
import {
    falseColour,
    formatValue,
    grey,
    luminanceTop,
    niceCeiling,
    quantile,
    srgbDecode,
    srgbEncode,
    ticks,
} from "../../src/colour_scale.js";

test("false colour runs from blue to red through green", () => {
    const [r0, g0, b0] = falseColour(0);
    const [r1, g1, b1] = falseColour(1);
    const [, gMid] = falseColour(0.5);
    assert.ok(b0 > r0 && b0 > g0, "the bottom is blue");
    assert.ok(r1 > g1 && r1 > b1, "the top is red");
    assert.ok(gMid > 0.4, "the middle is green");
    assert.deepEqual(falseColour(-3), falseColour(0));
    assert.deepEqual(falseColour(7), falseColour(1));
    assert.deepEqual(falseColour(NaN), falseColour(0));
});

test("grey is linear and clamped", () => {
    assert.deepEqual(grey(0.25), [0.25, 0.25, 0.25]);
    assert.deepEqual(grey(2), [1, 1, 1]);
    assert.deepEqual(grey(-1), [0, 0, 0]);
});

test("sRGB encoding round-trips", () => {
    for (const x of [0, 0.002, 0.2, 0.5, 1])
        assert.ok(Math.abs(srgbDecode(srgbEncode(x)) - x) < 1e-9);
    assert.ok(Math.abs(srgbEncode(0.5) - 0.7354) < 1e-3);
});

test("round legend tops and ticks", () => {
    assert.equal(niceCeiling(0), 1);
    assert.equal(niceCeiling(430), 500);
    assert.equal(niceCeiling(500), 500);
    assert.equal(niceCeiling(566), 600);
    assert.equal(niceCeiling(1.3), 1.5);
    assert.equal(niceCeiling(2.2), 2.5);
    assert.equal(niceCeiling(8.5), 10);
    assert.equal(niceCeiling(0.07), 0.08);
    assert.deepEqual(ticks(500, 5), [0, 100, 200, 300, 400, 500]);
});

test("luminance top ignores the brightest 2 %", () => {
    const values = new Float32Array(100).fill(100 * Math.PI);
    values[99] = 1e6; // an emitting panel
    assert.equal(quantile(values, 0.98), Math.fround(100 * Math.PI));
    assert.equal(luminanceTop(values), 100);
    assert.equal(quantile([], 0.5), 0);
});

test("values for people", () => {
    assert.equal(formatValue(512.34), "512");
    assert.equal(formatValue(51.234), "51.2");
    assert.equal(formatValue(5.1234), "5.12");
    assert.equal(formatValue(0.01234), "0.012");
    assert.equal(formatValue(0), "0");
    assert.equal(formatValue(NaN), "–");
});
