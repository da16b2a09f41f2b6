#!/usr/bin/env python3
"""Joins PNG frames of one size and colour type into an animated PNG (APNG), without re-encoding.

    python3 tests/tools/apng.py --fps 12 out.png frame_0000.png frame_0001.png ...

Each frame's filtered pixel data is kept as is (IDAT for the first frame, fdAT for the others), so
the result shows exactly the frames rtc wrote; it is only compressed again, at zlib's level 9. The
animation loops forever. Standard library only.
"""
import struct
import sys
import zlib

SIGNATURE = b"\x89PNG\r\n\x1a\n"


def chunks(data):
    if data[:8] != SIGNATURE:
        raise SystemExit("not a PNG file")
    at = 8
    while at < len(data):
        (length,) = struct.unpack(">I", data[at : at + 4])
        kind = data[at + 4 : at + 8]
        yield kind, data[at + 8 : at + 8 + length]
        at += 12 + length


def chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))


def main(argv):
    if len(argv) < 4 or argv[0] != "--fps":
        raise SystemExit(__doc__)
    fps, out, frames = int(argv[1]), argv[2], argv[3:]
    parsed = []
    for path in frames:
        with open(path, "rb") as f:
            parsed.append(list(chunks(f.read())))
    ihdr = parsed[0][0][1]
    width, height = struct.unpack(">II", ihdr[:8])
    result = [SIGNATURE, chunk(b"IHDR", ihdr), chunk(b"acTL", struct.pack(">II", len(frames), 0))]
    # The first frame's ancillary chunks before its image data (sRGB, gAMA, …).
    for kind, body in parsed[0][1:]:
        if kind == b"IDAT":
            break
        result.append(chunk(kind, body))
    seq = 0
    for n, cs in enumerate(parsed):
        if cs[0][1] != ihdr:
            raise SystemExit(f"{frames[n]}: another size or colour type than {frames[0]}")
        # fcTL: sequence, size, offset, delay 1/fps, dispose none, blend source.
        fctl = struct.pack(">IIIIIHHBB", seq, width, height, 0, 0, 1, fps, 0, 0)
        result.append(chunk(b"fcTL", fctl))
        seq += 1
        data = b"".join(body for kind, body in cs if kind == b"IDAT")
        body = zlib.compress(zlib.decompress(data), 9)
        if n == 0:
            result.append(chunk(b"IDAT", body))
        else:
            result.append(chunk(b"fdAT", struct.pack(">I", seq) + body))
            seq += 1
    result.append(chunk(b"IEND", b""))
    with open(out, "wb") as f:
        f.write(b"".join(result))


if __name__ == "__main__":
    main(sys.argv[1:])
