// Decodes the PNG screenshots Chromium writes (8-bit RGB or RGBA, not interlaced) into pixels,
// so tests can check what a person would see. Node's zlib does the inflating.
import { inflateSync } from "node:zlib";

/// {width, height, pixel(x, y) → [r, g, b]} of a PNG file's bytes.
export function decodePng(bytes) {
    const buffer = Buffer.from(bytes);
    if (buffer.readUInt32BE(0) !== 0x89504e47) throw new Error("not a PNG");
    let offset = 8;
    let width = 0,
        height = 0,
        channels = 0;
    const data = [];
    while (offset < buffer.length) {
        const length = buffer.readUInt32BE(offset);
        const type = buffer.toString("latin1", offset + 4, offset + 8);
        const chunk = buffer.subarray(offset + 8, offset + 8 + length);
        if (type === "IHDR") {
            width = chunk.readUInt32BE(0);
            height = chunk.readUInt32BE(4);
            const [depth, colour, , , interlace] = chunk.subarray(8, 13);
            channels = { 2: 3, 6: 4 }[colour];
            if (depth !== 8 || !channels || interlace !== 0)
                throw new Error("unsupported PNG layout");
        } else if (type === "IDAT") {
            data.push(chunk);
        }
        offset += 12 + length;
    }
    const raw = inflateSync(Buffer.concat(data));
    const stride = width * channels;
    const pixels = Buffer.alloc(stride * height);
    for (let y = 0; y < height; ++y) {
        const filter = raw[y * (stride + 1)];
        const line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
        const out = pixels.subarray(y * stride, (y + 1) * stride);
        const up = y > 0 ? pixels.subarray((y - 1) * stride, y * stride) : Buffer.alloc(stride);
        for (let i = 0; i < stride; ++i) {
            const a = i >= channels ? out[i - channels] : 0;
            const b = up[i];
            const c = i >= channels ? up[i - channels] : 0;
            let predictor = 0;
            if (filter === 1) predictor = a;
            else if (filter === 2) predictor = b;
            else if (filter === 3) predictor = (a + b) >> 1;
            else if (filter === 4) {
                const p = a + b - c;
                const pa = Math.abs(p - a),
                    pb = Math.abs(p - b),
                    pc = Math.abs(p - c);
                predictor = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
            }
            out[i] = (line[i] + predictor) & 0xff;
        }
    }
    return {
        width,
        height,
        pixel(x, y) {
            const at = Math.round(y) * stride + Math.round(x) * channels;
            return [pixels[at], pixels[at + 1], pixels[at + 2]];
        },
    };
}
