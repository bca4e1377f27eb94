#!/usr/bin/python3
"""Writes a .gltf whose one triangle hangs below a chain of DEPTH nodes, each the only child of
the one before, as exporters of rigged scans produce: a reader that recurses per level runs out
of stack. Usage: deep_gltf.py DEPTH OUT.gltf"""
import base64
import json
import struct
import sys

depth, out = int(sys.argv[1]), sys.argv[2]
positions = struct.pack("<9f", 0, 0, 0, 0.2, 0, 0, 0, 0, 0.2)
indices = struct.pack("<3H", 0, 1, 2) + b"\0\0"
data = positions + indices
nodes = [{"children": [i + 1]} for i in range(depth - 1)] + [{"mesh": 0}]
gltf = {
    "asset": {"version": "2.0"},
    "scene": 0,
    "scenes": [{"nodes": [0]}],
    "nodes": nodes,
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
    "buffers": [{"byteLength": len(data),
                 "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                    {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                   "min": [0, 0, 0], "max": [0.2, 0, 0.2]},
                  {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
}
with open(out, "w") as f:
    json.dump(gltf, f)
