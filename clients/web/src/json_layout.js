// A JSON document pretty-printed for showing an error at its JSON pointer (RFC 6901): the text
// as lines, and for every pointer the lines its value spans. Long strings (inlined OBJ or IES
// files) and long arrays of numbers are shortened: this is a view, not the document.

const MAX_STRING = 80;
const MAX_INLINE_ITEMS = 12;

const escapeToken = (key) => String(key).replaceAll("~", "~0").replaceAll("/", "~1");

function scalarText(value) {
    if (typeof value === "string" && value.length > MAX_STRING) {
        return `${JSON.stringify(value.slice(0, MAX_STRING))}… (${value.length} characters)`;
    }
    return JSON.stringify(value);
}

const isScalar = (v) => v === null || typeof v !== "object";

/// An array of scalars on one line, shortened past MAX_INLINE_ITEMS.
function inlineArray(items) {
    const shown = items.slice(0, MAX_INLINE_ITEMS).map(scalarText).join(", ");
    const more =
        items.length > MAX_INLINE_ITEMS ? `, … ${items.length - MAX_INLINE_ITEMS} more` : "";
    return `[${shown}${more}]`;
}

/// {lines: [string], spans: Map(pointer → {first, last})} of `value`.
export function layoutJson(value) {
    const lines = [];
    const spans = new Map();
    const visit = (v, pointer, indent, prefix, suffix) => {
        const first = lines.length;
        const pad = "  ".repeat(indent);
        if (isScalar(v)) {
            lines.push(`${pad}${prefix}${scalarText(v)}${suffix}`);
        } else if (Array.isArray(v) && v.every(isScalar)) {
            lines.push(`${pad}${prefix}${inlineArray(v)}${suffix}`);
            v.forEach((_, i) => spans.set(`${pointer}/${i}`, { first, last: first }));
        } else {
            const entries = Array.isArray(v) ? v.map((x, i) => [i, x]) : Object.entries(v);
            const [open, close] = Array.isArray(v) ? ["[", "]"] : ["{", "}"];
            if (!entries.length) {
                lines.push(`${pad}${prefix}${open}${close}${suffix}`);
            } else {
                lines.push(`${pad}${prefix}${open}`);
                entries.forEach(([key, x], i) => {
                    const label = Array.isArray(v) ? "" : `${JSON.stringify(key)}: `;
                    visit(
                        x,
                        `${pointer}/${escapeToken(key)}`,
                        indent + 1,
                        label,
                        i + 1 < entries.length ? "," : "",
                    );
                });
                lines.push(`${pad}${close}${suffix}`);
            }
        }
        spans.set(pointer, { first, last: lines.length - 1 });
    };
    visit(value, "", 0, "", "");
    return { lines, spans };
}

/// The lines to show for `pointer`: {from, to, first, last, exact}. Lines first..last are the
/// value's (or, for a pointer to something missing, its nearest existing parent's first line,
/// with exact false); from..to adds `context` lines around, at most `maxLines` in all.
export function excerpt(layout, pointer, context = 3, maxLines = 16) {
    let target = pointer;
    let span = layout.spans.get(target);
    while (!span && target !== "") {
        target = target.slice(0, target.lastIndexOf("/"));
        span = layout.spans.get(target);
    }
    const exact = target === pointer;
    const first = span.first;
    const last = exact ? Math.min(span.last, first + maxLines - 1) : first;
    const from = Math.max(0, first - context);
    const to = Math.min(layout.lines.length - 1, last + context, from + maxLines - 1);
    return { from, to, first, last: Math.min(last, to), exact };
}
