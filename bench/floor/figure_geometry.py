#!/usr/bin/env python3
"""The geometry of a figure for pita_cairo_floor (bench/floor/cairo_floor.cpp).

Reads the SVG pita wrote for a figure and the figure's scene, and prints what
the raw cairo program draws: every path of the SVG (stroked or filled, with
its colour and width, SVG path data as cairo wrote it) and every title of the
scene (a panel's method when it has none) as a text. Glyph outlines are left out: the floor draws the titles as
text, so that it, too, starts fontconfig.

    figure_geometry.py FIGURE.svg SCENE.json > GEOMETRY
"""
import json
import re
import sys
import xml.etree.ElementTree as ET

SVG = "{http://www.w3.org/2000/svg}"


def colour(style, key):
    """rgb(20%,20%,20%) of `key` in a style, and its opacity, as 0-1 numbers."""
    match = re.search(key + r":rgb\(([\d.]+)%,([\d.]+)%,([\d.]+)%\)", style)
    if not match:
        return None
    opacity = re.search(key + r"-opacity:([\d.]+)", style)
    rgb = [float(v) / 100.0 for v in match.groups()]
    return rgb + [float(opacity.group(1)) if opacity else 1.0]


def main():
    svg_path, scene_path = sys.argv[1], sys.argv[2]
    root = ET.parse(svg_path).getroot()
    width = float(root.get("width").rstrip("px"))
    height = float(root.get("height").rstrip("px"))
    print(f"{width:g} {height:g}")
    symbols = {id(p) for s in root.iter(SVG + "symbol") for p in s.iter(SVG + "path")}
    for path in root.iter(SVG + "path"):
        if id(path) in symbols or not path.get("d", "").strip():
            continue
        style = path.get("style", "")
        data = path.get("d").strip()
        if "fill:none" in style:
            rgba = colour(style, "stroke")
            width_match = re.search(r"stroke-width:([\d.]+)", style)
            if rgba:
                print("S", *(f"{v:g}" for v in rgba), width_match.group(1) if width_match else "1", data)
        else:
            rgba = colour(style, "fill") or [0.0, 0.0, 0.0, 1.0]
            print("F", *(f"{v:g}" for v in rgba), data)
    scene = json.load(open(scene_path))
    # A panel without a title of its own is titled by its method ("P1 Pa-Ca").
    titles = [scene.get("title", "")] + [p.get("title", p.get("method", "")) for p in scene.get("panels", [])]
    for i, title in enumerate(t for t in titles if t):
        print("T", 15 if i == 0 else 13, 20, 20 + 30 * i, title)


if __name__ == "__main__":
    main()
