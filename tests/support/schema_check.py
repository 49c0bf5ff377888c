#!/usr/bin/env python3
"""Validate JSON files against a JSON Schema; print "FILE: valid" or "FILE: invalid" per file.

Used by schema_agreement_test to check that the schema and the C++ parser agree. NaN and
Infinity literals are not JSON (RFC 8259), so they make a file invalid, as in the C++ parser.
"""
import json
import sys

import jsonschema


def refuse_constant(name):
    raise ValueError(f"{name} is not valid JSON")


def main():
    schema_path, *files = sys.argv[1:]
    with open(schema_path, encoding="utf-8") as f:
        schema = json.load(f)
    cls = jsonschema.validators.validator_for(schema)
    cls.check_schema(schema)
    validator = cls(schema)
    for path in files:
        try:
            with open(path, encoding="utf-8") as f:
                doc = json.load(f, parse_constant=refuse_constant)
            errors = list(validator.iter_errors(doc))
        except ValueError:
            errors = ["not JSON"]
        print(f"{path}: {'valid' if not errors else 'invalid'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
