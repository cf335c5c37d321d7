#!/usr/bin/python3
"""Writes a copy of an apitrace trace whose first glBufferData of 384 bytes declares 400: the
size argument lies about the blob that follows it, as a damaged or hostile trace may.

    lying_blob.py IN.trace OUT.trace

The trace is repacked with zlib (apitrace reads gzip traces), patched, and compressed again.
In apitrace's call encoding an argument is (index, type, value): size is argument 1 of type
UINT (4) and data argument 2 of type BLOB (8), each length a varint (384 = 0x80 0x03).
"""
import gzip
import subprocess
import sys
import tempfile

source, target = sys.argv[1], sys.argv[2]
with tempfile.NamedTemporaryFile(suffix=".trace") as repacked:
    subprocess.run(["apitrace", "repack", "-z", source, repacked.name], check=True, capture_output=True)
    raw = gzip.open(repacked.name).read()
honest = b"\x01\x04\x80\x03\x01\x02\x08\x80\x03"
if raw.count(honest) < 1:
    sys.exit("lying_blob.py: no glBufferData of 384 bytes in " + source)
with gzip.open(target, "wb") as out:
    out.write(raw.replace(honest, b"\x01\x04\x90\x03\x01\x02\x08\x80\x03", 1))
