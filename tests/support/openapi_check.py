#!/usr/bin/env python3
"""Check recorded HTTP exchanges with radiantd against proto/openapi.yaml.

Usage: openapi_check.py OPENAPI.yaml EXCHANGES.json

EXCHANGES.json is a list of objects, either
  {"method", "path" (the template, e.g. /v1/jobs/{id}), "status", "content_type", "body"}
or, for the data of one server-sent event,
  {"component": "RadiosityEvent", "body"}.
Every status must be declared for its operation, the content type must be the declared one, and
a JSON body must validate against the declared schema (OpenAPI 3.0 `nullable` is read as a union
with null; `$ref`s into proto/schema/*.json are followed). Prints one line per problem; exit 1
if there is any.
"""
import json
import pathlib
import sys
import warnings

import jsonschema
import yaml


def with_nulls(node):
    """OpenAPI 3.0 `nullable: true` → JSON Schema `anyOf [..., {type: null}]`."""
    if isinstance(node, list):
        return [with_nulls(n) for n in node]
    if not isinstance(node, dict):
        return node
    node = {k: with_nulls(v) for k, v in node.items()}
    if node.pop("nullable", False):
        return {"anyOf": [node, {"type": "null"}]}
    return node


def main():
    # RefResolver is deprecated in newer jsonschema but is what Debian 12's 4.10 offers.
    warnings.simplefilter("ignore", DeprecationWarning)
    spec_path = pathlib.Path(sys.argv[1]).resolve()
    exchanges = json.loads(pathlib.Path(sys.argv[2]).read_text(encoding="utf-8"))
    spec = with_nulls(yaml.safe_load(spec_path.read_text(encoding="utf-8")))
    base = spec_path.as_uri()
    store = {base: spec}
    # The JSON schemas the API refers to, under their file URL and their own $id.
    for schema_file in (spec_path.parent / "schema").glob("*.json"):
        schema = json.loads(schema_file.read_text(encoding="utf-8"))
        store[schema_file.as_uri()] = schema
        if "$id" in schema:
            store[schema["$id"]] = schema
    resolver = jsonschema.RefResolver(base, spec, store=store)

    def validate(schema, body, where):
        # A fresh resolver each time: a resolver keeps a scope stack while it validates.
        fresh = jsonschema.RefResolver(base, spec, store=store)
        validator = jsonschema.Draft202012Validator(schema, resolver=fresh)
        return [f"{where}: {'/'.join(map(str, e.absolute_path))}: {e.message}"
                for e in validator.iter_errors(body)]

    problems = []
    for x in exchanges:
        if "component" in x:
            schema = {"$ref": f"#/components/schemas/{x['component']}"}
            problems += validate(schema, x["body"], f"event {x['component']}")
            continue
        where = f"{x['method'].upper()} {x['path']} {x['status']}"
        operation = spec["paths"].get(x["path"], {}).get(x["method"].lower())
        if operation is None:
            problems.append(f"{where}: no such operation in the spec")
            continue
        response = operation["responses"].get(str(x["status"]))
        if response is None:
            problems.append(f"{where}: status not declared")
            continue
        if "$ref" in response:
            response = resolver.resolve(response["$ref"])[1]
        content = response.get("content")
        if not content:
            continue
        media = x["content_type"].split(";")[0].strip()
        if media not in content:
            problems.append(f"{where}: content type {media}, declared {sorted(content)}")
            continue
        if media != "application/json":
            continue
        try:
            body = json.loads(x["body"])
        except ValueError:
            problems.append(f"{where}: the body is not JSON")
            continue
        problems += validate(content[media]["schema"], body, where)
    for p in problems:
        print(p)
    print(f"{len(exchanges)} exchanges, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
