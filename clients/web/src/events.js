// radiantd's job events (GET /v1/jobs/{id}/events; docs/service.md, "Streaming radiosity"),
// decoded into what the view draws. The one module that knows the events' data layout: when
// the service changes its encoding, only this file follows.

export class EventFormatError extends Error {}

function need(condition, what) {
    if (!condition) throw new EventFormatError(`malformed event: ${what}`);
}

/// [[a, b, c], …] → a flat typed array of 3 per item, every item checked.
function flatTriples(rows, ArrayType, name) {
    need(Array.isArray(rows), `${name} is not an array`);
    const out = new ArrayType(rows.length * 3);
    rows.forEach((row, i) => {
        need(Array.isArray(row) && row.length === 3, `${name}[${i}] is not a triple`);
        for (let k = 0; k < 3; ++k) {
            need(Number.isFinite(row[k]), `${name}[${i}] is not numeric`);
            out[3 * i + k] = row[k];
        }
    });
    return out;
}

function numbers(values, ArrayType, name) {
    need(Array.isArray(values), `${name} is not an array`);
    need(values.every(Number.isFinite), `${name} holds a non-number`);
    return ArrayType.from(values);
}

/// `mesh`: the patch geometry of one mesh version (metres, triangles, each one's surface).
export function decodeMesh(data) {
    const positions = flatTriples(data.vertices, Float32Array, "vertices");
    const indices = flatTriples(data.triangles, Uint32Array, "triangles");
    const vertexCount = positions.length / 3;
    need(
        indices.every((i) => i < vertexCount),
        "a triangle names a missing vertex",
    );
    const triangleSurface = numbers(data.triangle_surface, Int32Array, "triangle_surface");
    need(triangleSurface.length === indices.length / 3, "triangle_surface length");
    return { meshVersion: data.mesh_version, positions, indices, triangleSurface };
}

/// `radiosity`: lm/m² leaving each triangle and vertex of mesh version `meshVersion`.
export function decodeRadiosity(data) {
    return {
        meshVersion: data.mesh_version,
        version: data.version,
        final: data.final === true,
        stage: data.stage,
        fraction: data.fraction,
        iterations: data.iterations,
        errorEstimate: data.error_estimate,
        elapsedSeconds: data.elapsed_seconds,
        triangleRadiosity: numbers(data.triangle_radiosity, Float32Array, "triangle_radiosity"),
        vertexRadiosity: numbers(data.vertex_radiosity, Float32Array, "vertex_radiosity"),
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
