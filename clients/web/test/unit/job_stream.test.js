import { test } from "node:test";
import assert from "node:assert/strict";
import { followJob } from "../../src/job_stream.js";

/// Stands in for the browser's EventSource: the test plays the service's events into it.
class FakeEventSource {
    static CONNECTING = 0;
    static OPEN = 1;
    static CLOSED = 2;
    static last = null;
    constructor(url) {
        this.url = url;
        this.readyState = FakeEventSource.OPEN;
        this.listeners = {};
        FakeEventSource.last = this;
    }
    addEventListener(kind, listener) {
        (this.listeners[kind] ??= []).push(listener);
    }
    close() {
        this.readyState = FakeEventSource.CLOSED;
    }
    emit(kind, data, lastEventId = "") {
        for (const listener of this.listeners[kind] ?? []) listener({ data, lastEventId });
    }
}

const f32 = (values) => Buffer.from(new Float32Array(values).buffer).toString("base64");
const i32 = (values) => Buffer.from(new Int32Array(values).buffer).toString("base64");
const mesh = JSON.stringify({
    mesh_version: 1,
    encoding: "base64-le",
    vertices: f32([0, 0, 0, 1, 0, 0, 0, 1, 0]),
    triangles: i32([0, 1, 2]),
    triangle_surface: i32([0]),
});
const radiosity = JSON.stringify({
    mesh_version: 1,
    version: 3,
    encoding: "base64-le",
    triangle_radiosity: f32([5]),
    vertex_radiosity: f32([1, 2, 3]),
});

test("events reach their handlers decoded, and the stream closes after done", () => {
    const seen = [];
    followJob(
        "a b",
        {
            open: () => seen.push(["open"]),
            mesh: (m) => seen.push(["mesh", m.meshVersion]),
            radiosity: (r) => seen.push(["radiosity", r.version]),
            progress: (p) => seen.push(["progress", p.fraction]),
            done: (d) => seen.push(["done", d.status]),
        },
        FakeEventSource,
    );
    const source = FakeEventSource.last;
    assert.equal(source.url, "v1/jobs/a%20b/events");
    source.emit("open");
    source.emit("mesh", mesh);
    source.emit("radiosity", radiosity);
    source.emit("progress", '{"status":"running","fraction":0.5}');
    source.emit("done", '{"status":"done"}');
    assert.equal(source.readyState, FakeEventSource.CLOSED);
    source.emit("progress", '{"status":"running","fraction":0.9}'); // after close: ignored
    assert.deepEqual(seen, [
        ["open"],
        ["mesh", 1],
        ["radiosity", 3],
        ["progress", 0.5],
        ["done", "done"],
    ]);
});

test("a reconnecting stream is left to retry; a closed one or a malformed event is an error", () => {
    const errors = [];
    followJob("j", { error: (e) => errors.push(e.message) }, FakeEventSource);
    let source = FakeEventSource.last;
    source.readyState = FakeEventSource.CONNECTING;
    source.emit("error");
    assert.deepEqual(errors, []);
    source.readyState = FakeEventSource.CLOSED;
    source.emit("error");
    assert.deepEqual(errors, ["the event stream of job j failed"]);

    followJob(
        "k",
        { error: (e) => errors.push(e.message), mesh: () => assert.fail("drawn") },
        FakeEventSource,
    );
    source = FakeEventSource.last;
    source.emit("mesh", '{"vertices": 3}');
    assert.match(errors[1], /malformed event/);
    assert.equal(source.readyState, FakeEventSource.CLOSED);
});

test("a repeat of earlier values gets them from the event that carried them", () => {
    const seen = [];
    const errors = [];
    followJob(
        "j",
        {
            radiosity: (r) => seen.push([r.version, Array.from(r.vertexRadiosity)]),
            error: (e) => errors.push(e.message),
        },
        FakeEventSource,
    );
    const source = FakeEventSource.last;
    source.emit("mesh", mesh, "5");
    source.emit("radiosity", radiosity, "6");
    source.emit("radiosity", '{"mesh_version":1,"version":4,"values_event":6}', "7");
    assert.deepEqual(seen, [
        [3, [1, 2, 3]],
        [4, [1, 2, 3]],
    ]);
    assert.deepEqual(errors, []);
    // Values the stream never carried: an error, not a picture of nothing.
    source.emit("radiosity", '{"mesh_version":1,"version":5,"values_event":99}', "8");
    assert.equal(seen.length, 2);
    assert.match(errors[0], /did not carry/);
    assert.equal(source.readyState, FakeEventSource.CLOSED);
});
