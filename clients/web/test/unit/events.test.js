import { test } from "node:test";
import assert from "node:assert/strict";
import { decodeEvent, EventFormatError } from "../../src/events.js";

/// The service's encoding: base64 of little-endian float32 or int32 values.
const f32 = (values) => Buffer.from(new Float32Array(values).buffer).toString("base64");
const i32 = (values) => Buffer.from(new Int32Array(values).buffer).toString("base64");

const mesh = {
    id: "j",
    mesh_version: 2,
    encoding: "base64-le",
    vertices: f32([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0.5]),
    triangles: i32([0, 1, 2, 1, 3, 2]),
    triangle_surface: i32([0, 1]),
};

test("a mesh event becomes flat typed arrays", () => {
    const m = decodeEvent("mesh", JSON.stringify(mesh));
    assert.equal(m.meshVersion, 2);
    assert.deepEqual(Array.from(m.positions), [0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0.5]);
    assert.ok(m.indices instanceof Uint32Array);
    assert.deepEqual(Array.from(m.indices), [0, 1, 2, 1, 3, 2]);
    assert.deepEqual(Array.from(m.triangleSurface), [0, 1]);
});

test("a radiosity event keeps its versions and values", () => {
    const r = decodeEvent(
        "radiosity",
        JSON.stringify({
            id: "j",
            mesh_version: 2,
            version: 7,
            final: false,
            stage: "shooting",
            fraction: 0.5,
            iterations: 3,
            error_estimate: 0.02,
            elapsed_seconds: 1.5,
            encoding: "base64-le",
            triangle_radiosity: f32([10, 20]),
            vertex_radiosity: f32([1, 2, 3, 4.5]),
        }),
    );
    assert.equal(r.meshVersion, 2);
    assert.equal(r.valuesEvent, null);
    assert.equal(r.version, 7);
    assert.equal(r.final, false);
    assert.equal(r.errorEstimate, 0.02);
    assert.deepEqual(Array.from(r.vertexRadiosity), [1, 2, 3, 4.5]);
    assert.deepEqual(Array.from(r.triangleRadiosity), [10, 20]);
});

test("a radiosity event that repeats earlier values names their event and has none", () => {
    const r = decodeEvent(
        "radiosity",
        '{"mesh_version":2,"version":8,"error_estimate":null,"values_event":41}',
    );
    assert.equal(r.version, 8);
    assert.equal(r.valuesEvent, 41);
    assert.equal(r.errorEstimate, null);
    assert.equal(r.vertexRadiosity, null);
});

test("progress and done", () => {
    const p = decodeEvent(
        "progress",
        '{"status":"running","stage":"gather","fraction":0.25,"error_estimate":0.1}',
    );
    assert.deepEqual(
        [p.status, p.stage, p.fraction, p.errorEstimate],
        ["running", "gather", 0.25, 0.1],
    );
    assert.deepEqual(decodeEvent("done", '{"id":"j","status":"failed","error":"boom"}'), {
        status: "failed",
        error: "boom",
    });
    assert.deepEqual(decodeEvent("done", '{"id":"j","status":"done"}'), {
        status: "done",
        error: null,
    });
});

test("malformed events are refused, not drawn", () => {
    const bad = [
        ["mesh", "{"],
        ["mesh", "null"],
        ["mesh", JSON.stringify({ ...mesh, triangles: i32([0, 1, 9]) })],
        ["mesh", JSON.stringify({ ...mesh, triangles: i32([0, -1, 2]) })],
        ["mesh", JSON.stringify({ ...mesh, vertices: f32([0, 0]) })],
        ["mesh", JSON.stringify({ ...mesh, vertices: f32([0, 0, NaN]) })],
        ["mesh", JSON.stringify({ ...mesh, vertices: "AAA" })],
        ["mesh", JSON.stringify({ ...mesh, vertices: "not base64!" })],
        ["mesh", JSON.stringify({ ...mesh, triangle_surface: i32([0]) })],
        ["mesh", JSON.stringify({ ...mesh, encoding: undefined })],
        [
            "radiosity",
            JSON.stringify({
                encoding: "base64-le",
                vertex_radiosity: f32([1, Infinity]),
                triangle_radiosity: f32([]),
            }),
        ],
        ["radiosity", JSON.stringify({ vertex_radiosity: [1, 2], triangle_radiosity: [] })],
        ["radiosity", '{"values_event":"41"}'],
        ["nonsense", "{}"],
    ];
    for (const [kind, text] of bad) {
        assert.throws(() => decodeEvent(kind, text), EventFormatError, `${kind} ${text}`);
    }
});
