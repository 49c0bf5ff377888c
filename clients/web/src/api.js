// radiantd's JSON API (proto/openapi.yaml), relative to the page, so the viewer also works
// behind a proxy that serves the service under a path prefix.

/// An error answer of the service: {"error": {code, message, pointer, problems}}.
export class ServiceError extends Error {
    constructor(status, error) {
        super(error.message || `HTTP ${status}`);
        this.status = status;
        this.code = error.code || "http_error";
        this.pointer = typeof error.pointer === "string" ? error.pointer : "";
        const problems = Array.isArray(error.problems) ? error.problems : [];
        this.problems = problems.length
            ? problems.map((p) => ({
                  pointer: String(p.pointer ?? ""),
                  message: String(p.message),
              }))
            : [{ pointer: this.pointer, message: this.message }];
    }
}

async function call(method, path, { body, accept = "application/json" } = {}) {
    const headers = { Accept: accept };
    if (body !== undefined) headers["Content-Type"] = "application/json";
    let response;
    try {
        response = await fetch(path, { method, headers, body });
    } catch (e) {
        throw new ServiceError(0, {
            code: "unreachable",
            message: `cannot reach radiantd: ${e.message}`,
        });
    }
    const text = await response.text();
    let json = null;
    try {
        json = text ? JSON.parse(text) : null;
    } catch {
        // Not JSON: reported below when it was an error, else as it is.
    }
    if (!response.ok) {
        throw new ServiceError(
            response.status,
            json?.error ?? { message: `HTTP ${response.status}: ${text.slice(0, 200)}` },
        );
    }
    return json;
}

const jobPath = (id) => `v1/jobs/${encodeURIComponent(id)}`;

/// POST /v1/jobs with the scene's JSON text; resolves to {id, status}.
export const submitJob = (sceneText) => call("POST", "v1/jobs", { body: sceneText });
export const getJob = (id) => call("GET", jobPath(id));
export const cancelJob = (id) => call("DELETE", jobPath(id));
/// The radiant-result/1 document (while running: its latest state).
export const getResult = (id) => call("GET", `${jobPath(id)}/result`);
export const listJobs = (limit = 20) => call("GET", `v1/jobs?limit=${limit}`);
