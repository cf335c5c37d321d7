#!/usr/bin/python3
"""Whether two imported scenes of the same frame say the same thing: exit 0 when they do, 1 with
the differences listed when not.

    same_scene.py A/scene.json B/scene.json

Names the importers choose differ by capture (apitrace numbers objects by their GL names,
RenderDoc by its resource ids), so every file a scene names is compared by its bytes. Two
representations of the same state are made one:
- a uniform of value zero that one capture lists and the other does not (RenderDoc lists every
  active uniform; a trace holds only the uniforms the application set, and an unset one reads 0);
- a texture's mip chain: a trace holds the glGenerateMipmap call (generate_mipmap), a RenderDoc
  capture the levels the driver made; both are compared by level 0 (tessref's generated levels
  are llvmpipe's, docs/textures.md).
"""
import hashlib
import json
import os
import sys


def normalize(path):
    base = os.path.dirname(os.path.abspath(path))
    scene = json.load(open(path))
    buffers = scene.pop("buffers", {})

    def file_digest(name):
        with open(os.path.join(base, name), "rb") as f:
            return "sha256:" + hashlib.sha256(f.read()).hexdigest()[:16]

    def fix(value, key=None):
        if isinstance(value, dict):
            out = {}
            for k, v in value.items():
                if k == "buffer" and isinstance(v, str):
                    out[k] = file_digest(buffers[v]["file"])
                elif k in ("vertex", "tess_control", "tess_evaluation", "fragment", "path") and isinstance(v, str):
                    out[k] = file_digest(v)
                elif k == "levels":
                    out["path"] = file_digest(v[0])
                elif k == "generate_mipmap":
                    continue
                elif k == "uniforms":
                    out[k] = {n: u for n, u in v.items() if any(x != 0 for x in u)}
                else:
                    out[k] = fix(v, k)
            return out
        if isinstance(value, list):
            return [fix(v) for v in value]
        return value

    scene = fix(scene)
    scene.pop("description", None)
    return scene


def differences(a, b, where=""):
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                yield "%s.%s: only in %s" % (where, k, "the first" if k in a else "the second")
            else:
                yield from differences(a[k], b[k], "%s.%s" % (where, k))
    elif isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        for i, (x, y) in enumerate(zip(a, b)):
            yield from differences(x, y, "%s.%d" % (where, i))
    elif a != b:
        yield "%s: %r != %r" % (where, a, b)


found = list(differences(normalize(sys.argv[1]), normalize(sys.argv[2])))
for line in found:
    print(line)
print("same scene" if not found else "%d differences" % len(found))
sys.exit(1 if found else 0)
