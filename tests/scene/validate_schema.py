#!/usr/bin/env python3
"""Validates JSON documents against schema/scene.schema.json with an
independent validator, Python's jsonschema (Draft 7; Debian python3-jsonschema).

    validate_schema.py SCHEMA

Reads one JSON document per line from standard input and answers each with
one line, {"valid": bool, "errors": [{"pointer": "/layers/0/text",
"message": "..."}, ...]}, flushed at once (so that one process serves a whole
test run). Used by tests/scene/test_schema.cpp; pita itself never reads the
schema.
"""
import json
import sys

import jsonschema


def pointer(path):
    return "".join("/" + str(part).replace("~", "~0").replace("/", "~1") for part in path)


def main():
    with open(sys.argv[1], encoding="utf-8") as f:
        schema = json.load(f)
    jsonschema.Draft7Validator.check_schema(schema)
    validator = jsonschema.Draft7Validator(schema)
    for line in sys.stdin:
        document = json.loads(line)
        errors = [{"pointer": pointer(e.absolute_path), "message": e.message}
                  for e in validator.iter_errors(document)]
        sys.stdout.write(json.dumps({"valid": not errors, "errors": errors}) + "\n")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
