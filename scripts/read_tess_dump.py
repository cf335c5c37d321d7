#!/usr/bin/env python3
"""Reads a `tessref render --dump-tess FILE` binary dump (format: io/tess_dump.h).

Plain Python (struct), no numpy. As a module: records(path) yields one tuple per tessellated
vertex, (patch_id, (u, v, w), (px, py, pz), (nx, ny, nz)), in the draw's order. As a script:

    scripts/read_tess_dump.py DUMP [--patch N] [--limit K]

prints the record count and patch count, then the records (of patch N only, the first K), one
per line as the text dump writes them: "patch_id u v w px py pz nx ny nz" (%.9g).
"""
import argparse
import struct
import sys

MAGIC = b"TESSDUMP"
HEADER = struct.Struct("<8sII")        # magic, version, record size
RECORD = struct.Struct("<I3f3f3f")     # patch_id, tess_coord, position, normal


def records(path):
    with open(path, "rb") as f:
        head = f.read(HEADER.size)
        if len(head) < HEADER.size:
            raise ValueError(f"{path}: shorter than the {HEADER.size}-byte header")
        magic, version, size = HEADER.unpack(head)
        if magic != MAGIC or version != 1 or size != RECORD.size:
            raise ValueError(f"{path}: not a tessref dump (magic {magic!r}, version {version}, "
                             f"record size {size}; expected {MAGIC!r}, 1, {RECORD.size})")
        while True:
            raw = f.read(RECORD.size)
            if not raw:
                return
            if len(raw) < RECORD.size:
                raise ValueError(f"{path}: cut short inside a record")
            r = RECORD.unpack(raw)
            yield r[0], r[1:4], r[4:7], r[7:10]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dump")
    ap.add_argument("--patch", type=int, help="only this patch's records")
    ap.add_argument("--limit", type=int, help="print at most this many records")
    a = ap.parse_args()
    try:
        rows = list(records(a.dump))
    except (OSError, ValueError) as e:
        print(f"read_tess_dump: {e}", file=sys.stderr)
        return 2
    patches = len({r[0] for r in rows})
    print(f"# {len(rows)} records, {patches} patches")
    print("# patch_id u v w px py pz nx ny nz")
    shown = 0
    for patch, tc, p, n in rows:
        if a.patch is not None and patch != a.patch:
            continue
        if a.limit is not None and shown >= a.limit:
            break
        print(patch, " ".join("%.9g" % x for x in (*tc, *p, *n)))
        shown += 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
