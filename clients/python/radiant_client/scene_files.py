"""Scenes as the service takes them: every file a scene names, inlined.

``radiant solve`` and ``radiant validate`` read the files a scene names (``obj_file``,
``gltf_file``, and a luminaire distribution's ``ies_file`` / ``ldt_file``) relative to the scene
file's directory. The service has no such directory: it takes only the inline alternatives
(``obj`` + ``mtl``, ``gltf`` as base64 ``.glb``, ``ies``, ``ldt``), so the client reads the files
and puts their content in the scene before it sends it.

A file that cannot be read is refused like the CLI refuses it: a :class:`SceneFileError` with the
pointer of the reference (``/surfaces/3/obj_file``) and ``cannot read PATH: why``.
"""

from __future__ import annotations

import base64
import copy
import json
import os
import struct
from pathlib import Path
from typing import Any, Dict, List, Mapping, Optional, Tuple, Union
from urllib.parse import unquote

from .errors import SceneFileError

#: The largest file the CLI reads for a scene (``proto::ParseLimits::max_bytes``, 64 MiB); the
#: service refuses larger bodies (413) too.
MAX_FILE_BYTES = 64 * 1024 * 1024

SceneSource = Union[Mapping[str, Any], str, "os.PathLike[str]"]


def load_scene(scene_or_path: SceneSource,
               base_dir: Union[str, "os.PathLike[str]", None] = None) -> Dict[str, Any]:
    """The scene as the service takes it, as a dict.

    ``scene_or_path`` is a scene (a dict, not changed) or the path of a ``radiant-scene/1`` JSON
    file. File references resolve against the scene file's directory, or for a dict against
    ``base_dir`` (default: the current directory). Raises :class:`SceneFileError` when the scene
    file (or a file it names) cannot be read or is not JSON.
    """
    scene, body = scene_body(scene_or_path, None, base_dir)
    if scene is None:
        where = str(scene_or_path)
        try:
            json.loads(body)
        except ValueError as e:
            raise SceneFileError("", f"{where}: not JSON: {e}", where) from None
        raise SceneFileError("", "a scene must be a JSON object", where)
    return scene


def scene_body(scene_or_path: SceneSource, settings: Optional[Mapping[str, Any]] = None,
               base_dir: Union[str, "os.PathLike[str]", None] = None
               ) -> Tuple[Optional[Dict[str, Any]], bytes]:
    """The scene to submit (None when the file is not a JSON object) and the request body.

    A scene file is sent as it is unless a file reference or ``settings`` changed it, so that
    the service judges exactly what ``radiant validate`` would (a file that is not JSON, a
    coordinate that overflows a double, and so on, are refused at the same pointer).
    """
    if isinstance(scene_or_path, Mapping):
        scene: Any = copy.deepcopy(dict(scene_or_path))
        directory = Path(base_dir) if base_dir is not None else Path.cwd()
        raw = None
    else:
        path = Path(scene_or_path)
        raw = _read_bytes(path, "")
        try:
            scene = json.loads(_decode(raw))
        except ValueError:
            return None, raw
        directory = Path(base_dir) if base_dir is not None else path.parent
    if not isinstance(scene, dict):
        return None, raw if raw is not None else _dump(scene)
    changed = inline_files(scene, directory) > 0
    if settings:
        base = scene.get("settings")
        scene["settings"] = {**(base if isinstance(base, dict) else {}), **settings}
        changed = True
    return scene, raw if raw is not None and not changed else _dump(scene)


def _dump(scene: Any) -> bytes:
    return json.dumps(scene, ensure_ascii=False, separators=(",", ":")).encode("utf-8")


def inline_files(scene: Dict[str, Any], directory: Union[str, "os.PathLike[str]"]) -> int:
    """Replaces, in place, every file reference of ``scene`` by the file's content; returns how
    many it replaced.

    A reference whose inline alternative is already there is left alone, so that the service
    reports the conflict at its pointer; so is one that is not a string.
    """
    directory = Path(directory)
    count = 0
    surfaces = scene.get("surfaces")
    for i, surface in enumerate(surfaces if isinstance(surfaces, list) else []):
        if not isinstance(surface, dict):
            continue
        pointer = f"/surfaces/{i}"
        if _is_reference(surface, "obj_file", "obj"):
            path = directory / surface["obj_file"]
            text = _read_text(path, pointer + "/obj_file")
            if "mtl" not in surface:
                mtl = _mtl_text(text, path.parent, pointer + "/obj_file")
                if mtl is not None:
                    surface["mtl"] = mtl
            _replace(surface, "obj_file", "obj", text)
            count += 1
        if _is_reference(surface, "gltf_file", "gltf"):
            path = directory / surface["gltf_file"]
            glb = _self_contained_glb(path, pointer + "/gltf_file")
            _replace(surface, "gltf_file", "gltf", base64.b64encode(glb).decode("ascii"))
            count += 1
    luminaires = scene.get("luminaires")
    for i, luminaire in enumerate(luminaires if isinstance(luminaires, list) else []):
        distribution = luminaire.get("distribution") if isinstance(luminaire, dict) else None
        if not isinstance(distribution, dict):
            continue
        for reference, inline in (("ies_file", "ies"), ("ldt_file", "ldt")):
            if _is_reference(distribution, reference, inline):
                pointer = f"/luminaires/{i}/distribution/{reference}"
                text = _read_text(directory / distribution[reference], pointer)
                _replace(distribution, reference, inline, text)
                count += 1
    return count


def _is_reference(obj: Dict[str, Any], reference: str, inline: str) -> bool:
    return isinstance(obj.get(reference), str) and obj[reference] != "" and inline not in obj


def _replace(obj: Dict[str, Any], reference: str, inline: str, value: str) -> None:
    """Puts ``inline`` where ``reference`` was, keeping the other keys' order."""
    items = [(inline if k == reference else k, value if k == reference else v)
             for k, v in obj.items()]
    obj.clear()
    obj.update(items)


def _read_bytes(path: Path, pointer: str) -> bytes:
    try:
        size = path.stat().st_size
        if size > MAX_FILE_BYTES:
            raise SceneFileError(
                pointer, f"cannot read {path}: over the limit of {MAX_FILE_BYTES} bytes", str(path))
        return path.read_bytes()
    except OSError as e:
        raise SceneFileError(pointer, f"cannot read {path}: {e.strerror or e}", str(path)) from None


def _read_text(path: Path, pointer: str) -> str:
    """The file as text. The CLI hands the bytes to its parsers as they are; JSON needs Unicode,
    so a file that is not UTF-8 is read as Latin-1 (old IES files often are): the parsers only
    look at its ASCII numbers and keywords."""
    return _decode(_read_bytes(path, pointer))


def _decode(data: bytes) -> str:
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return data.decode("latin-1")


def _mtllib_names(obj_text: str) -> List[List[str]]:
    """The file names of each ``mtllib`` statement, split as tinyobjloader splits them (on
    spaces, with ``\\`` escaping the next character)."""
    statements = []
    for line in obj_text.splitlines():
        line = line.lstrip(" \t")
        if not (line.startswith("mtllib") and line[6:7] in (" ", "\t")):
            continue
        names, token, escaping = [], "", False
        for ch in line[7:]:
            if escaping:
                escaping = False
            elif ch == "\\":
                escaping = True
                continue
            elif ch == " ":
                if token:
                    names.append(token)
                token = ""
                continue
            token += ch
        if token:
            names.append(token)
        statements.append(names)
    return statements


def _mtl_text(obj_text: str, obj_directory: Path, pointer: str) -> Optional[str]:
    """The MTL text answering the OBJ's ``mtllib`` statements, or None if none names a file.

    From a file, each statement loads the first of its names that exists in the OBJ file's
    directory; a missing one is skipped (its faces then have no material, as with the CLI).
    Inline, one MTL text answers every statement, so the files found are joined.
    """
    loaded: List[str] = []
    texts: List[str] = []
    for names in _mtllib_names(obj_text):
        for name in names:
            if name in loaded:
                continue
            path = obj_directory / name
            if path.is_file():
                texts.append(_read_text(path, pointer))
                loaded.append(name)
                break
    return "\n".join(texts) if texts else None


# --- glTF -----------------------------------------------------------------------------------

_GLB_MAGIC = b"glTF"
_CHUNK_JSON = 0x4E4F534A
_CHUNK_BIN = 0x004E4942


def _split_glb(data: bytes, path: Path, pointer: str) -> Tuple[Dict[str, Any], Optional[bytes]]:
    def bad(why: str) -> SceneFileError:
        return SceneFileError(pointer, f"cannot read {path}: {why}", str(path))

    if len(data) < 20:
        raise bad("a .glb shorter than its header")
    _, _, length = struct.unpack_from("<4sII", data, 0)
    offset, document, binary = 12, None, None
    while offset + 8 <= min(length, len(data)):
        chunk_length, chunk_type = struct.unpack_from("<II", data, offset)
        chunk = data[offset + 8:offset + 8 + chunk_length]
        if chunk_type == _CHUNK_JSON and document is None:
            try:
                document = json.loads(chunk.decode("utf-8"))
            except ValueError as e:
                raise bad(f"the .glb's JSON chunk is not JSON: {e}") from None
        elif chunk_type == _CHUNK_BIN and binary is None:
            binary = chunk
        offset += 8 + chunk_length
    if not isinstance(document, dict):
        raise bad("a .glb without a JSON chunk")
    return document, binary


def _pack_glb(document: Dict[str, Any], binary: Optional[bytes]) -> bytes:
    """A binary glTF of ``document`` and, when there is one, its BIN chunk (glTF 2.0 §4.4)."""
    text = json.dumps(document, separators=(",", ":")).encode("utf-8")
    text += b" " * (-len(text) % 4)
    chunks = struct.pack("<II", len(text), _CHUNK_JSON) + text
    if binary is not None:
        binary += b"\0" * (-len(binary) % 4)
        chunks += struct.pack("<II", len(binary), _CHUNK_BIN) + binary
    return struct.pack("<4sII", _GLB_MAGIC, 2, 12 + len(chunks)) + chunks


def _mime_type(name: str) -> str:
    lower = name.lower()
    if lower.endswith(".png"):
        return "image/png"
    if lower.endswith((".jpg", ".jpeg")):
        return "image/jpeg"
    return "application/octet-stream"


def _self_contained_glb(path: Path, pointer: str) -> bytes:
    """The ``.glb`` the service can read without files: a ``.glb`` as it is when it names no
    other file, else (and for a ``.gltf``) repacked with every external buffer and image in it.

    The service reads inline models only from a ``.glb`` and refuses one that names a file.
    """
    data = _read_bytes(path, pointer)
    if data[:4] == _GLB_MAGIC:
        document, binary = _split_glb(data, path, pointer)
    else:
        try:
            document = json.loads(data.decode("utf-8"))
        except ValueError as e:
            raise SceneFileError(pointer, f"cannot read {path}: neither a .glb nor glTF JSON: {e}",
                                 str(path)) from None
        if not isinstance(document, dict):
            raise SceneFileError(pointer, f"cannot read {path}: not a glTF document", str(path))
        binary = None

    def external(item: Any) -> bool:
        return (isinstance(item, dict) and isinstance(item.get("uri"), str)
                and not item["uri"].startswith("data:"))

    buffers = document.get("buffers") if isinstance(document.get("buffers"), list) else []
    images = document.get("images") if isinstance(document.get("images"), list) else []
    if data[:4] == _GLB_MAGIC and not any(external(x) for x in buffers + images):
        return data

    def content(uri: str) -> bytes:
        return _read_bytes(path.parent / unquote(uri), pointer)

    for index, buffer in enumerate(buffers):
        if not (isinstance(buffer, dict) and isinstance(buffer.get("uri"), str)):
            continue
        uri = buffer["uri"]
        if index == 0 and binary is None:
            # The first buffer becomes the BIN chunk: raw bytes, not base64 inside base64.
            if uri.startswith("data:"):
                try:
                    binary = base64.b64decode(uri.split(",", 1)[1])
                except (IndexError, ValueError):
                    continue  # a broken data URI: the service reports it
            else:
                binary = content(uri)
            del buffer["uri"]
        elif not uri.startswith("data:"):
            buffer["uri"] = ("data:application/octet-stream;base64,"
                             + base64.b64encode(content(uri)).decode("ascii"))
    for image in images:
        if external(image):
            uri = image["uri"]
            image["uri"] = (f"data:{_mime_type(uri)};base64,"
                            + base64.b64encode(content(uri)).decode("ascii"))
    return _pack_glb(document, binary)
