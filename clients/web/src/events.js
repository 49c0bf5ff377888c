// radiantd's job events (GET /v1/jobs/{id}/events; docs/service.md, "Streaming radiosity"),
// decoded into what the view draws. The one module that knows the events' data layout: when
// the service changes its encoding, only this file follows.

export class EventFormatError extends Error {}

function need(condition, what) {
    if (!condition) throw new EventFormatError(`malformed event: ${what}`);
}

/// A base64 string of little-endian binary values → a typed array of `ArrayType`'s elements
/// (the service's `"encoding": "base64-le"`), every value checked with `valid`.
function base64Values(text, ArrayType, name, valid) {
    need(typeof text === "string", `${name} is not a base64 string`);
    let binary;
    try {
        binary = atob(text);
    } catch {
        throw new EventFormatError(`malformed event: ${name} is not base64`);
    }
    const size = ArrayType.BYTES_PER_ELEMENT;
    need(binary.length % size === 0, `${name} is not a whole number of values`);
    const bytes = Uint8Array.from(binary, (c) => c.charCodeAt(0));
    const view = new DataView(bytes.buffer);
    const out = new ArrayType(binary.length / size);
    for (let i = 0; i < out.length; ++i) {
        const value =
            ArrayType === Float32Array
                ? view.getFloat32(i * size, true)
                : view.getInt32(i * size, true);
        need(valid(value), `${name}[${i}] is out of range`);
        out[i] = value;
    }
    return out;
}

const finite = (v) => Number.isFinite(v);
const nonNegative = (v) => v >= 0;

function needEncoding(data) {
    need(data.encoding === "base64-le", `unknown encoding ${data.encoding}`);
}

/// `mesh`: the patch geometry of one mesh version (metres, triangles, each one's surface).
export function decodeMesh(data) {
    needEncoding(data);
    const positions = base64Values(data.vertices, Float32Array, "vertices", finite);
    need(positions.length % 3 === 0, "vertices is not a list of triples");
    const indices = Uint32Array.from(
        base64Values(data.triangles, Int32Array, "triangles", nonNegative),
    );
    need(indices.length % 3 === 0, "triangles is not a list of triples");
    const vertexCount = positions.length / 3;
    need(
        indices.every((i) => i < vertexCount),
        "a triangle names a missing vertex",
    );
    const triangleSurface = base64Values(
        data.triangle_surface,
        Int32Array,
        "triangle_surface",
        nonNegative,
    );
    need(triangleSurface.length === indices.length / 3, "triangle_surface length");
    return { meshVersion: data.mesh_version, positions, indices, triangleSurface };
}

/// `radiosity`: lm/m² leaving each triangle and vertex of mesh version `meshVersion`. A repeat of
/// values this stream already carried has none, only `valuesEvent`, that event's id
/// (job_stream.js fills them in).
export function decodeRadiosity(data) {
    const repeat = data.values_event !== undefined;
    if (repeat) {
        need(Number.isInteger(data.values_event), "values_event is not an event id");
    } else {
        needEncoding(data);
    }
    const values = (name) => (repeat ? null : base64Values(data[name], Float32Array, name, finite));
    return {
        meshVersion: data.mesh_version,
        version: data.version,
        final: data.final === true,
        stage: data.stage,
        fraction: data.fraction,
        iterations: data.iterations,
        errorEstimate: data.error_estimate,
        elapsedSeconds: data.elapsed_seconds,
        valuesEvent: repeat ? data.values_event : null,
        triangleRadiosity: values("triangle_radiosity"),
        vertexRadiosity: values("vertex_radiosity"),
    };
}

/// `progress`: the job's status and its solve's progress.
export function decodeProgress(data) {
    return {
        status: data.status,
        stage: data.stage,
        fraction: data.fraction,
        iterations: data.iterations,
        errorEstimate: data.error_estimate,
        elapsedSeconds: data.elapsed_seconds,
    };
}

/// `done`: the job's final status (done, failed, cancelled) and, when failed, why.
export function decodeDone(data) {
    return { status: data.status, error: data.error ?? null };
}

const decoders = {
    mesh: decodeMesh,
    radiosity: decodeRadiosity,
    progress: decodeProgress,
    done: decodeDone,
};

export const EVENT_KINDS = Object.keys(decoders);

/// One event's `data:` text → its decoded form; throws EventFormatError when malformed.
export function decodeEvent(kind, text) {
    const decode = decoders[kind];
    need(decode !== undefined, `unknown event ${kind}`);
    let data;
    try {
        data = JSON.parse(text);
    } catch (e) {
        throw new EventFormatError(`malformed event: ${kind} data is not JSON (${e.message})`);
    }
    need(data !== null && typeof data === "object", `${kind} data is not an object`);
    return decode(data);
}
