// A glTF model as the service reads it: one self-contained binary .glb (glTF 2.0 §4.4), with
// every external buffer and image put inside — as clients/python's scene_files.py repacks it.

const GLB_MAGIC = 0x46546c67; // "glTF"
const CHUNK_JSON = 0x4e4f534a;
const CHUNK_BIN = 0x004e4942;

export function toBase64(bytes) {
    let text = "";
    for (let i = 0; i < bytes.length; i += 0x8000) {
        text += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
    }
    return btoa(text);
}

function fromBase64(text) {
    return Uint8Array.from(atob(text), (c) => c.charCodeAt(0));
}

const isGlb = (bytes) =>
    bytes.length >= 4 &&
    new DataView(bytes.buffer, bytes.byteOffset).getUint32(0, true) === GLB_MAGIC;

/// A .glb's JSON document and BIN chunk (null when it has none).
function splitGlb(bytes) {
    if (bytes.length < 20) throw new Error("a .glb shorter than its header");
    const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    const length = Math.min(view.getUint32(8, true), bytes.length);
    let offset = 12;
    let document = null;
    let binary = null;
    while (offset + 8 <= length) {
        const chunkLength = view.getUint32(offset, true);
        const chunkType = view.getUint32(offset + 4, true);
        const chunk = bytes.subarray(offset + 8, offset + 8 + chunkLength);
        if (chunkType === CHUNK_JSON && document === null) {
            try {
                document = JSON.parse(new TextDecoder().decode(chunk));
            } catch (e) {
                throw new Error(`the .glb's JSON chunk is not JSON: ${e.message}`);
            }
        } else if (chunkType === CHUNK_BIN && binary === null) {
            binary = chunk;
        }
        offset += 8 + chunkLength;
    }
    if (document === null || typeof document !== "object")
        throw new Error("a .glb without a JSON chunk");
    return { document, binary };
}

function padded(bytes, multiple, fill) {
    const out = new Uint8Array(Math.ceil(bytes.length / multiple) * multiple).fill(fill);
    out.set(bytes);
    return out;
}

/// A binary glTF of `document` and, when there is one, its BIN chunk.
function packGlb(document, binary) {
    const text = padded(new TextEncoder().encode(JSON.stringify(document)), 4, 0x20);
    const bin = binary ? padded(binary, 4, 0) : null;
    const total = 12 + 8 + text.length + (bin ? 8 + bin.length : 0);
    const out = new Uint8Array(total);
    const view = new DataView(out.buffer);
    view.setUint32(0, GLB_MAGIC, true);
    view.setUint32(4, 2, true);
    view.setUint32(8, total, true);
    view.setUint32(12, text.length, true);
    view.setUint32(16, CHUNK_JSON, true);
    out.set(text, 20);
    if (bin) {
        const at = 20 + text.length;
        view.setUint32(at, bin.length, true);
        view.setUint32(at + 4, CHUNK_BIN, true);
        out.set(bin, at + 8);
    }
    return out;
}

function mimeType(name) {
    const lower = name.toLowerCase();
    if (lower.endsWith(".png")) return "image/png";
    if (lower.endsWith(".jpg") || lower.endsWith(".jpeg")) return "image/jpeg";
    return "application/octet-stream";
}

const isExternal = (item) =>
    item !== null &&
    typeof item === "object" &&
    typeof item.uri === "string" &&
    !item.uri.startsWith("data:");

/// The .glb the service can read without files: a .glb as it is when it names no other file,
/// else (and for a .gltf) repacked with every external buffer and image in it. `read(uri)`
/// resolves to the bytes of a file the model names.
export async function selfContainedGlb(bytes, read) {
    let document;
    let binary = null;
    const glb = isGlb(bytes);
    if (glb) {
        ({ document, binary } = splitGlb(bytes));
    } else {
        try {
            document = JSON.parse(new TextDecoder().decode(bytes));
        } catch (e) {
            throw new Error(`neither a .glb nor glTF JSON: ${e.message}`);
        }
        if (document === null || typeof document !== "object" || Array.isArray(document)) {
            throw new Error("not a glTF document");
        }
    }
    const buffers = Array.isArray(document.buffers) ? document.buffers : [];
    const images = Array.isArray(document.images) ? document.images : [];
    if (glb && ![...buffers, ...images].some(isExternal)) return bytes;

    for (const [index, buffer] of buffers.entries()) {
        if (buffer === null || typeof buffer !== "object" || typeof buffer.uri !== "string")
            continue;
        const uri = buffer.uri;
        if (index === 0 && binary === null) {
            // The first buffer becomes the BIN chunk: raw bytes, not base64 inside base64.
            if (uri.startsWith("data:")) {
                try {
                    binary = fromBase64(uri.slice(uri.indexOf(",") + 1));
                } catch {
                    continue; // a broken data URI: the service reports it
                }
            } else {
                binary = await read(uri);
            }
            delete buffer.uri;
        } else if (!uri.startsWith("data:")) {
            buffer.uri = `data:application/octet-stream;base64,${toBase64(await read(uri))}`;
        }
    }
    for (const image of images) {
        if (isExternal(image))
            image.uri = `data:${mimeType(image.uri)};base64,${toBase64(await read(image.uri))}`;
    }
    return packGlb(document, binary);
}
