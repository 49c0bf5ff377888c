// Scenes as the service takes them: every file a scene names, inlined — the same way
// `radiant solve` reads them and clients/python/radiant_client/scene_files.py inlines them. The
// service never reads files: it takes only the inline forms (`obj` + `mtl`, `gltf` as a base64
// .glb, `ies`, `ldt`). A file that cannot be read is a SceneFileError at the reference's pointer
// (`/surfaces/3/obj_file`), shown like the service's own errors.
import { selfContainedGlb, toBase64 } from "./glb.js";

/// The largest file the CLI reads for a scene (64 MiB); the service refuses larger bodies too.
export const MAX_FILE_BYTES = 64 * 1024 * 1024;

export class SceneFileError extends Error {
    constructor(pointer, message) {
        super(message);
        this.pointer = pointer;
        this.problems = [{ pointer, message }];
    }
}

/// `name` in folder `dir` (paths in scenes use `/`; the reader resolves `..`).
export const joinPath = (dir, name) => (dir ? `${dir}/${name}` : name);

export const dirname = (path) => path.split("/").slice(0, -1).join("/");

/// UTF-8, else Latin-1 (old IES files often are; their parsers only read ASCII).
export function decodeText(bytes) {
    try {
        return new TextDecoder("utf-8", { fatal: true }).decode(bytes);
    } catch {
        return new TextDecoder("latin1").decode(bytes);
    }
}

function tooLarge(path, size) {
    return size > MAX_FILE_BYTES ? `${path}: over the limit of ${MAX_FILE_BYTES} bytes` : null;
}

/// Reads the files dropped with a scene: `files` are File objects, found by their relative path
/// (a dropped folder) or, failing that, by name.
export function droppedFileReader(files) {
    return async (path) => {
        const name = path.split("/").pop();
        const file =
            files.find((f) => (f.webkitRelativePath || "").endsWith(path)) ??
            files.find((f) => f.name === name);
        if (!file) throw new Error(`${path} was not dropped with the scene`);
        const why = tooLarge(path, file.size);
        if (why) throw new Error(why);
        return new Uint8Array(await file.arrayBuffer());
    };
}

/// Reads files next to a scene served at `sceneUrl` (the viewer's examples).
export function urlReader(sceneUrl, fetchImpl = globalThis.fetch) {
    return async (path) => {
        const response = await fetchImpl(new URL(path, sceneUrl));
        if (!response.ok) throw new Error(`HTTP ${response.status}`);
        const bytes = new Uint8Array(await response.arrayBuffer());
        const why = tooLarge(path, bytes.length);
        if (why) throw new Error(why);
        return bytes;
    };
}

/// `read(path)` → bytes, or a SceneFileError "cannot read PATH: why" at `pointer`.
async function readAt(read, path, pointer) {
    try {
        return await read(path);
    } catch (e) {
        throw new SceneFileError(pointer, `cannot read ${path}: ${e.message}`);
    }
}

function isReference(obj, reference, inline) {
    return typeof obj[reference] === "string" && obj[reference] !== "" && !(inline in obj);
}

/// Puts `inline` where `reference` was, keeping the other keys' order.
function replaceKey(obj, reference, inline, value) {
    const entries = Object.entries(obj).map(([k, v]) =>
        k === reference ? [inline, value] : [k, v],
    );
    for (const key of Object.keys(obj)) delete obj[key];
    Object.assign(obj, Object.fromEntries(entries));
}

/// The file names of each `mtllib` statement, split as tinyobjloader splits them (on spaces,
/// with `\` escaping the next character).
export function mtllibNames(objText) {
    const statements = [];
    for (const raw of objText.split(/\r?\n/)) {
        const line = raw.replace(/^[ \t]+/, "");
        if (!(line.startsWith("mtllib") && (line[6] === " " || line[6] === "\t"))) continue;
        const names = [];
        let token = "";
        let escaping = false;
        for (const ch of line.slice(7)) {
            if (escaping) {
                escaping = false;
            } else if (ch === "\\") {
                escaping = true;
                continue;
            } else if (ch === " ") {
                if (token) names.push(token);
                token = "";
                continue;
            }
            token += ch;
        }
        if (token) names.push(token);
        statements.push(names);
    }
    return statements;
}

/// The MTL text answering the OBJ's `mtllib` statements, or null. As the CLI does, each
/// statement loads the first of its names that can be read; a missing one is skipped. Inline,
/// one MTL text answers every statement, so the files found are joined.
async function mtlText(objText, objDir, read) {
    const loaded = [];
    const texts = [];
    for (const names of mtllibNames(objText)) {
        for (const name of names) {
            if (loaded.includes(name)) continue;
            let bytes;
            try {
                bytes = await read(joinPath(objDir, name));
            } catch {
                continue;
            }
            texts.push(decodeText(bytes));
            loaded.push(name);
            break;
        }
    }
    return texts.length ? texts.join("\n") : null;
}

/// Replaces, in place, every file reference of `scene` by the file's content (paths relative to
/// the scene's folder, read with `read(path)` → Uint8Array); resolves to how many it replaced.
/// A reference whose inline form is already there is left alone, so that the service reports the
/// conflict at its pointer; so is one that is not a string.
export async function inlineFiles(scene, read) {
    let count = 0;
    const surfaces = Array.isArray(scene.surfaces) ? scene.surfaces : [];
    for (const [i, surface] of surfaces.entries()) {
        if (surface === null || typeof surface !== "object") continue;
        const pointer = `/surfaces/${i}`;
        if (isReference(surface, "obj_file", "obj")) {
            const path = surface.obj_file;
            const text = decodeText(await readAt(read, path, `${pointer}/obj_file`));
            if (!("mtl" in surface)) {
                const mtl = await mtlText(text, dirname(path), read);
                if (mtl !== null) surface.mtl = mtl;
            }
            replaceKey(surface, "obj_file", "obj", text);
            ++count;
        }
        if (isReference(surface, "gltf_file", "gltf")) {
            const path = surface.gltf_file;
            const at = `${pointer}/gltf_file`;
            const bytes = await readAt(read, path, at);
            let glb;
            try {
                glb = await selfContainedGlb(bytes, (uri) =>
                    read(joinPath(dirname(path), decodeURIComponent(uri))),
                );
            } catch (e) {
                throw new SceneFileError(at, `cannot read ${path}: ${e.message}`);
            }
            replaceKey(surface, "gltf_file", "gltf", toBase64(glb));
            ++count;
        }
    }
    const luminaires = Array.isArray(scene.luminaires) ? scene.luminaires : [];
    for (const [i, luminaire] of luminaires.entries()) {
        const distribution =
            luminaire && typeof luminaire === "object" ? luminaire.distribution : null;
        if (
            distribution === null ||
            typeof distribution !== "object" ||
            Array.isArray(distribution)
        )
            continue;
        for (const [reference, inline] of [
            ["ies_file", "ies"],
            ["ldt_file", "ldt"],
        ]) {
            if (!isReference(distribution, reference, inline)) continue;
            const path = distribution[reference];
            const bytes = await readAt(read, path, `/luminaires/${i}/distribution/${reference}`);
            replaceKey(distribution, reference, inline, decodeText(bytes));
            ++count;
        }
    }
    return count;
}

/// What to submit for a scene file's text: {scene, body}. The text is sent as it is unless a
/// file reference changed the scene, so the service judges exactly what `radiant validate`
/// would; `scene` is null when the text is not a JSON object (the service then says why).
export async function sceneBody(text, read) {
    let scene;
    try {
        scene = JSON.parse(text);
    } catch {
        return { scene: null, body: text };
    }
    if (scene === null || typeof scene !== "object" || Array.isArray(scene))
        return { scene: null, body: text };
    const changed = (await inlineFiles(scene, read)) > 0;
    return { scene, body: changed ? JSON.stringify(scene) : text };
}
