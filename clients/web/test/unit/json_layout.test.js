import { test } from "node:test";
import assert from "node:assert/strict";
import { excerpt, layoutJson } from "../../src/json_layout.js";

const scene = {
    format: "radiant-scene/1",
    materials: { wall: { reflectance: 1.5 }, "a/b~c": { reflectance: 0.2 } },
    surfaces: [
        {
            name: "floor",
            material: "wall",
            polygon: [
                [0, 0, 0],
                [4, 0, 0],
                [4, 4, 0],
            ],
        },
    ],
    luminaires: [{ distribution: { ies: "x".repeat(500) } }],
};

test("every pointer knows its lines", () => {
    const { lines, spans } = layoutJson(scene);
    const line = (p) => lines[spans.get(p).first];
    assert.match(line("/materials/wall/reflectance"), /"reflectance": 1\.5/);
    assert.match(line("/materials/a~1b~0c"), /"a\/b~c": \{/);
    assert.match(line("/surfaces/0/polygon/2"), /\[4, 4, 0\]/);
    assert.match(line("/surfaces/0/polygon/2/1"), /\[4, 4, 0\]/);
    const polygon = spans.get("/surfaces/0/polygon");
    assert.equal(polygon.last - polygon.first, 4);
    assert.equal(spans.get("").first, 0);
    assert.equal(spans.get("").last, lines.length - 1);
    assert.deepEqual(JSON.parse(layoutJson({ a: [1, 2], b: {} }).lines.join("\n")), {
        a: [1, 2],
        b: {},
    });
});

test("long strings are shortened", () => {
    const { lines, spans } = layoutJson(scene);
    const text = lines[spans.get("/luminaires/0/distribution/ies").first];
    assert.ok(text.length < 150);
    assert.match(text, /500 characters/);
});

test("an excerpt around the pointer, or around its nearest parent", () => {
    const layout = layoutJson(scene);
    const at = excerpt(layout, "/materials/wall/reflectance", 2);
    assert.equal(at.exact, true);
    assert.equal(at.first, at.last);
    assert.match(layout.lines[at.first], /1\.5/);
    assert.equal(at.to - at.from, 4);
    const missing = excerpt(layout, "/surfaces/0/nonsense/3");
    assert.equal(missing.exact, false);
    assert.match(layout.lines[missing.first], /^\s*\{$/);
    assert.equal(missing.first, layout.spans.get("/surfaces/0").first);
});
