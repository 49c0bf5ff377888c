"""The files a scene names are inlined as the CLI reads them (no service needed)."""

from __future__ import annotations

import base64
import json
import os
import struct
import tempfile
import unittest
from pathlib import Path

from radiant_client import SceneFileError, inline_files, load_scene
from radiant_client.scene_files import _mtllib_names, scene_body

from support import FURNISHED_OFFICE, SOURCE_DIR

GOOD = SOURCE_DIR / "tests" / "data" / "good"


def references(value):
    """Every key of a nested document that ends with _file."""
    if isinstance(value, dict):
        return [k for k in value if k.endswith("_file")] + [
            k for v in value.values() for k in references(v)]
    if isinstance(value, list):
        return [k for v in value for k in references(v)]
    return []


def glb_chunks(data: bytes):
    magic, version, length = struct.unpack_from("<4sII", data)
    assert (magic, version, length) == (b"glTF", 2, len(data))
    chunks, offset = [], 12
    while offset < len(data):
        size, kind = struct.unpack_from("<II", data, offset)
        chunks.append((kind, data[offset + 8:offset + 8 + size]))
        offset += 8 + size
    return chunks


class FurnishedOffice(unittest.TestCase):
    def test_every_reference_is_replaced_by_the_files_content(self):
        original = json.loads(FURNISHED_OFFICE.read_text())
        scene = load_scene(FURNISHED_OFFICE)
        self.assertTrue(references(original))
        self.assertEqual(references(scene), [])
        directory = FURNISHED_OFFICE.parent
        furniture = next(s for s in scene["surfaces"] if s["name"] == "furniture")
        self.assertEqual(furniture["obj"], (directory / "furniture.obj").read_text())
        # The OBJ's mtllib is answered by the MTL text.
        self.assertEqual(furniture["mtl"], (directory / "furniture.mtl").read_text())
        ies = (directory / "downlight.ies").read_text()
        for luminaire in scene["luminaires"]:
            self.assertEqual(luminaire["distribution"], {"ies": ies})
        # Everything else is as in the file, in the same order.
        self.assertEqual(list(furniture), ["name", "obj", "mtl"])
        self.assertEqual(scene["sensors"], original["sensors"])

    def test_a_dict_resolves_against_base_dir_and_is_not_changed(self):
        original = json.loads(FURNISHED_OFFICE.read_text())
        before = json.dumps(original)
        scene = load_scene(original, base_dir=FURNISHED_OFFICE.parent)
        self.assertEqual(json.dumps(original), before)
        self.assertEqual(references(scene), [])
        with self.assertRaises(SceneFileError):
            load_scene(original, base_dir=SOURCE_DIR)  # no furniture.obj there

    def test_a_dict_resolves_against_the_current_directory_by_default(self):
        original = json.loads(FURNISHED_OFFICE.read_text())
        cwd = os.getcwd()
        try:
            os.chdir(FURNISHED_OFFICE.parent)
            self.assertEqual(references(load_scene(original)), [])
        finally:
            os.chdir(cwd)

    def test_a_file_without_references_is_sent_byte_for_byte(self):
        path = SOURCE_DIR / "proto" / "examples" / "simple-room.json"
        scene, body = scene_body(path)
        self.assertEqual(body, path.read_bytes())
        self.assertEqual(scene["name"], "simple-room")
        scene, body = scene_body(path, {"tolerance": 0.1})
        self.assertEqual(json.loads(body)["settings"], {"tolerance": 0.1})

    def test_a_file_that_is_not_json_is_sent_as_it_is_for_the_service_to_judge(self):
        path = SOURCE_DIR / "tests" / "data" / "bad" / "syntax-trailing-comma.json"
        self.assertEqual(scene_body(path), (None, path.read_bytes()))
        with self.assertRaises(SceneFileError) as caught:
            load_scene(path)
        self.assertEqual(caught.exception.pointer, "")
        with self.assertRaises(SceneFileError) as caught:
            load_scene(path.with_name("not-an-object.json"))
        self.assertEqual(caught.exception.message, "a scene must be a JSON object")


class References(unittest.TestCase):
    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory()
        self.dir = Path(self._tmp.name)

    def tearDown(self):
        self._tmp.cleanup()

    def scene(self, **surface):
        return {"format": "radiant-scene/1", "materials": {"w": {"reflectance": 0.5}},
                "surfaces": [{"name": "room", "material": "w",
                              "box": {"min": [0, 0, 0], "max": [4, 4, 3]}},
                             {"name": "model", **surface}]}

    def test_a_missing_file_is_refused_at_its_pointer_as_the_cli_does(self):
        with self.assertRaises(SceneFileError) as caught:
            load_scene(self.scene(obj_file="nowhere.obj"), self.dir)
        e = caught.exception
        self.assertEqual(e.pointer, "/surfaces/1/obj_file")
        self.assertTrue(e.message.startswith(f"cannot read {self.dir / 'nowhere.obj'}: "), e)
        self.assertEqual(e.problems[0].pointer, "/surfaces/1/obj_file")
        scene = {"format": "radiant-scene/1", "materials": {}, "surfaces": [],
                 "luminaires": [{"name": "a", "position": [0, 0, 0]},
                                {"name": "b", "position": [0, 0, 0],
                                 "distribution": {"ldt_file": "x.ldt"}}]}
        with self.assertRaises(SceneFileError) as caught:
            load_scene(scene, self.dir)
        self.assertEqual(caught.exception.pointer, "/luminaires/1/distribution/ldt_file")

    def test_eulumdat_and_latin1_ies_texts(self):
        (self.dir / "a.ldt").write_bytes(b"EULUMDAT text\r\n")
        (self.dir / "b.ies").write_bytes(b"IESNA:LM-63-2002\n[TEST] 10\xb0 beam\n")
        scene = {"luminaires": [{"distribution": {"ldt_file": "a.ldt"}},
                                {"distribution": {"ies_file": "b.ies"}}]}
        self.assertEqual(inline_files(scene, self.dir), 2)
        self.assertEqual(scene["luminaires"][0]["distribution"], {"ldt": "EULUMDAT text\r\n"})
        self.assertEqual(scene["luminaires"][1]["distribution"]["ies"],
                         "IESNA:LM-63-2002\n[TEST] 10\u00b0 beam\n")

    def test_a_reference_beside_its_inline_alternative_is_left_for_the_service(self):
        scene = self.scene(obj="v 0 0 0", obj_file="nowhere.obj")
        self.assertEqual(inline_files(scene, self.dir), 0)
        self.assertEqual(scene["surfaces"][1]["obj_file"], "nowhere.obj")

    def test_mtllib_statements(self):
        self.assertEqual(_mtllib_names("mtllib a.mtl  b.mtl\n  mtllib\tx\nmtllib my\\ file.mtl\n"
                                       "# mtllib c.mtl\nmtllibx d.mtl\n"),
                         [["a.mtl", "b.mtl"], ["x"], ["my file.mtl"]])
        sub = self.dir / "models"
        sub.mkdir()
        (sub / "m.obj").write_text("mtllib gone.mtl found.mtl\nmtllib other.mtl\nv 0 0 0\n")
        (sub / "found.mtl").write_text("newmtl a\nKd 0.5 0.5 0.5\n")
        (sub / "other.mtl").write_text("newmtl b\nKd 0.2 0.2 0.2\n")
        scene = self.scene(obj_file="models/m.obj")
        inline_files(scene, self.dir)
        # MTL files are relative to the OBJ file; the first one found of each statement is read.
        self.assertEqual(scene["surfaces"][1]["mtl"],
                         "newmtl a\nKd 0.5 0.5 0.5\n\nnewmtl b\nKd 0.2 0.2 0.2\n")
        # A given mtl stays; an OBJ whose MTL files are all missing gets none.
        scene = self.scene(obj_file="models/m.obj", mtl="newmtl c\n")
        inline_files(scene, self.dir)
        self.assertEqual(scene["surfaces"][1]["mtl"], "newmtl c\n")
        (sub / "lonely.obj").write_text("mtllib gone.mtl\nv 0 0 0\n")
        scene = self.scene(obj_file="models/lonely.obj")
        inline_files(scene, self.dir)
        self.assertNotIn("mtl", scene["surfaces"][1])

    def test_a_glb_is_inlined_as_base64(self):
        scene = json.loads((GOOD / "import-gltf.json").read_text())
        inline_files(scene, GOOD)
        model = scene["surfaces"][2]
        self.assertNotIn("gltf_file", model)
        self.assertEqual(base64.b64decode(model["gltf"]),
                         (GOOD / "models" / "table.glb").read_bytes())

    def test_a_gltf_with_external_files_becomes_a_self_contained_glb(self):
        chunks = glb_chunks((GOOD / "models" / "table.glb").read_bytes())
        document = json.loads(chunks[0][1])
        binary = chunks[1][1][:document["buffers"][0]["byteLength"]]
        (self.dir / "table data.bin").write_bytes(binary)
        (self.dir / "tex.png").write_bytes(b"\x89PNG fake")
        document["buffers"][0]["uri"] = "table%20data.bin"
        document["images"] = [{"uri": "tex.png"}]
        (self.dir / "table.gltf").write_text(json.dumps(document))
        scene = self.scene(gltf_file="table.gltf")
        inline_files(scene, self.dir)
        packed = glb_chunks(base64.b64decode(scene["surfaces"][1]["gltf"]))
        self.assertEqual([kind for kind, _ in packed], [0x4E4F534A, 0x004E4942])
        packed_document = json.loads(packed[0][1])
        self.assertNotIn("uri", packed_document["buffers"][0])
        self.assertEqual(packed[1][1][:len(binary)], binary)
        self.assertEqual(packed_document["images"][0]["uri"],
                         "data:image/png;base64," + base64.b64encode(b"\x89PNG fake").decode())
        self.assertEqual(packed_document["meshes"], document["meshes"])

        (self.dir / "table data.bin").unlink()
        with self.assertRaises(SceneFileError) as caught:
            inline_files(self.scene(gltf_file="table.gltf"), self.dir)
        self.assertEqual(caught.exception.pointer, "/surfaces/1/gltf_file")
        self.assertIn("table data.bin", caught.exception.message)


if __name__ == "__main__":
    unittest.main()
