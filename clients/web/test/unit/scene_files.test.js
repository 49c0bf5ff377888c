import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { inlineFiles, mtllibNames, SceneFileError, sceneBody } from "../../src/scene_files.js";
import { selfContainedGlb } from "../../src/glb.js";

const examples = join(dirname(fileURLToPath(import.meta.url)), "../../../../proto/examples");
const fromFolder = (folder) => async (path) => new Uint8Array(readFileSync(join(folder, path)));

test("the furnished office inlines its OBJ, MTL and IES files like the CLI reads them", async () => {
    const folder = join(examples, "furnished-office");
    const text = readFileSync(join(folder, "furnished-office.json"), "utf8");
    const { scene, body } = await sceneBody(text, fromFolder(folder));
    const sent = JSON.parse(body);
    assert.deepEqual(sent, scene);
    const model = sent.surfaces.find((s) => "obj" in s);
    assert.equal(model.obj, readFileSync(join(folder, "furniture.obj"), "utf8"));
    assert.equal(model.mtl, readFileSync(join(folder, "furniture.mtl"), "utf8"));
    assert.ok(!("obj_file" in model));
    // The inline key takes the reference's place.
    const keys = Object.keys(JSON.parse(text).surfaces.find((s) => "obj_file" in s));
    assert.deepEqual(
        Object.keys(model).slice(0, keys.length),
        keys.map((k) => (k === "obj_file" ? "obj" : k)),
    );
    const ies = readFileSync(join(folder, "downlight.ies"), "utf8");
    assert.ok(sent.luminaires.length > 0);
    for (const l of sent.luminaires) assert.equal(l.distribution.ies, ies);
});

test("a scene without references is sent as its own text", async () => {
    const text = readFileSync(join(examples, "simple-room.json"), "utf8");
    const { body } = await sceneBody(text, async () => assert.fail("nothing to read"));
    assert.equal(body, text);
    assert.deepEqual(await sceneBody("{not json", null), { scene: null, body: "{not json" });
    assert.deepEqual(await sceneBody("[1]", null), { scene: null, body: "[1]" });
});

test("a missing file is an error at the reference's pointer", async () => {
    const scene = {
        surfaces: [
            { name: "a", polygon: [] },
            { name: "m", obj_file: "chair.obj" },
        ],
        luminaires: [{ distribution: { ldt_file: "lamp.ldt" } }],
    };
    const read = async (path) => {
        throw new Error(`${path} was not dropped with the scene`);
    };
    await assert.rejects(inlineFiles(scene, read), (e) => {
        assert.ok(e instanceof SceneFileError);
        assert.equal(e.pointer, "/surfaces/1/obj_file");
        assert.equal(e.message, "cannot read chair.obj: chair.obj was not dropped with the scene");
        return true;
    });
    scene.surfaces.pop();
    await assert.rejects(inlineFiles(scene, read), {
        pointer: "/luminaires/0/distribution/ldt_file",
    });
});

test("a reference beside its inline form is left for the service to refuse", async () => {
    const scene = {
        surfaces: [{ obj_file: "a.obj", obj: "v 0 0 0" }],
        luminaires: [{ distribution: { ies_file: 3 } }],
    };
    assert.equal(await inlineFiles(scene, async () => assert.fail("no read")), 0);
});

test("mtllib statements split like tinyobjloader", () => {
    assert.deepEqual(
        mtllibNames("v 1 2 3\nmtllib a.mtl b.mtl\n  mtllib my\\ file.mtl\nmtllibx c"),
        [["a.mtl", "b.mtl"], ["my file.mtl"]],
    );
});

test("an OBJ's first readable MTL per statement, joined", async () => {
    const files = {
        "m/x.obj": "mtllib gone.mtl one.mtl\nmtllib two.mtl\n",
        "m/one.mtl": "newmtl one",
        "m/two.mtl": "newmtl two",
    };
    const read = async (p) => {
        if (!(p in files)) throw new Error("missing");
        return new TextEncoder().encode(files[p]);
    };
    const scene = { surfaces: [{ obj_file: "m/x.obj" }] };
    assert.equal(await inlineFiles(scene, read), 1);
    assert.equal(scene.surfaces[0].mtl, "newmtl one\nnewmtl two");
});

test("non-UTF-8 text (an old IES file) is read as Latin-1", async () => {
    const scene = { luminaires: [{ distribution: { ies_file: "old.ies" } }] };
    await inlineFiles(scene, async () => Uint8Array.from([0x49, 0x45, 0x53, 0xb0]));
    assert.equal(scene.luminaires[0].distribution.ies, "IES°");
});

test("a .gltf with an external buffer becomes one .glb", async () => {
    const bin = Uint8Array.from([1, 2, 3, 4, 5]);
    const gltf = { asset: { version: "2.0" }, buffers: [{ uri: "mesh.bin", byteLength: 5 }] };
    const glb = await selfContainedGlb(
        new TextEncoder().encode(JSON.stringify(gltf)),
        async (uri) => {
            assert.equal(uri, "mesh.bin");
            return bin;
        },
    );
    const view = new DataView(glb.buffer);
    assert.equal(view.getUint32(0, true), 0x46546c67);
    assert.equal(view.getUint32(8, true), glb.length);
    const jsonLength = view.getUint32(12, true);
    const doc = JSON.parse(new TextDecoder().decode(glb.subarray(20, 20 + jsonLength)));
    assert.deepEqual(doc.buffers, [{ byteLength: 5 }]);
    const binAt = 20 + jsonLength;
    assert.equal(view.getUint32(binAt + 4, true), 0x004e4942);
    assert.deepEqual(Array.from(glb.subarray(binAt + 8, binAt + 13)), [1, 2, 3, 4, 5]);
    // A self-contained .glb is passed through untouched.
    assert.equal(await selfContainedGlb(glb, async () => assert.fail("no read")), glb);
});
