import { test } from "node:test";
import assert from "node:assert/strict";
import { sensorLayouts } from "../../src/sensor_geometry.js";

test("a scene grid expands row-major, u fastest, in metres", () => {
    const scene = {
        units: "cm",
        sensors: [
            {
                name: "wp",
                normal: [0, 0, 1],
                grid: { origin: [0, 0, 80], u: [400, 0, 0], v: [0, 200, 0], nu: 2, nv: 2 },
            },
        ],
    };
    const [wp] = sensorLayouts({ sensors: [{ name: "wp", illuminance: [1, 2, 3, 4] }] }, scene);
    assert.deepEqual(wp.points, [
        [1, 0.5, 0.8],
        [3, 0.5, 0.8],
        [1, 1.5, 0.8],
        [3, 1.5, 0.8],
    ]);
    assert.deepEqual(wp.cell, { u: [2, 0, 0], v: [0, 1, 0] });
    assert.deepEqual(wp.normal, [0, 0, 1]);
});

test("a result's work-plane grid is used as it is", () => {
    const grid = {
        nu: 3,
        nv: 1,
        origin: [0, 0, 0.8],
        u: [3, 0, 0],
        v: [0, 1, 0],
        points: [
            [0.5, 0.5, 0.8],
            [2.5, 0.5, 0.8],
        ],
        cells: [
            [0, 0],
            [2, 0],
        ],
    };
    const [wp] = sensorLayouts({ sensors: [{ name: "wp", illuminance: [1, 2], grid }] }, null);
    assert.deepEqual(wp.points, grid.points);
    assert.deepEqual(wp.cell, { u: [1, 0, 0], v: [0, 1, 0] });
});

test("points, and sets whose points are unknown", () => {
    const scene = {
        units: "mm",
        sensors: [{ name: "desk", points: [[1000, 2000, 750]], normal: [0, 1, 0] }],
    };
    const result = {
        sensors: [
            { name: "desk", illuminance: [300] },
            { name: "other", illuminance: [1] },
        ],
    };
    const [desk, other] = sensorLayouts(result, scene);
    assert.deepEqual(desk.points, [[1, 2, 0.75]]);
    assert.equal(desk.cell, null);
    assert.deepEqual(desk.normal, [0, 1, 0]);
    assert.deepEqual(other.points, []);
    assert.deepEqual(sensorLayouts(null, null), []);
});
