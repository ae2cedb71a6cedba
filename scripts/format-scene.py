#!/usr/bin/env python3
"""Rewrites scene files in the repository's layout: one top-level field per
line, and one keyframe, layer or panel per line. Usage: scripts/format-scene.py FILE..."""
import json
import sys


def compact(value):
    return json.dumps(value, ensure_ascii=False, separators=(", ", ": "))


def field(key, value, indent):
    pad = " " * indent
    if isinstance(value, list) and value and all(isinstance(v, (dict, str)) for v in value):
        items = [f"{pad}  {compact(v)}" for v in value]
        return f'{pad}"{key}": [\n' + ",\n".join(items) + f"\n{pad}]"
    return f'{pad}"{key}": {compact(value)}'


def format_scene(scene):
    return "{\n" + ",\n".join(field(k, v, 2) for k, v in scene.items()) + "\n}\n"


for path in sys.argv[1:]:
    with open(path, encoding="utf-8") as f:
        scene = json.load(f)
    with open(path, "w", encoding="utf-8") as f:
        f.write(format_scene(scene))
