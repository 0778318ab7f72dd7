#!/usr/bin/env python3
"""pymavlink's side of the codec benchmark: parses the stream bench/run.sh wrote (MixedStream)
with pymavlink's MAVLink parser and prints frames per second, on one thread.

  pymavlink_parse.py FILE [--frames N] [--repeat R] [--chunk BYTES] [--json]

Two modes, as the JMH benchmarks: "stream" feeds the bytes in chunks of --chunk bytes to
MAVLink.parse_buffer (frames split across chunks); "datagrams" feeds one frame per parse_buffer
call. pymavlink's parser always decodes what it frames (checksum, struct unpack, message object),
so both modes compare with the Java side's framing + decoding. Each mode runs --repeat times on a
fresh parser; the best and the median repetition are reported (other load on the machine only ever
makes a repetition slower). Every repetition must yield exactly --frames messages, none bad.

Accelerated paths: pymavlink 2.4.50 has no native (C) parser any more (mavnative is gone and
MAVLink(use_native=True) is ignored); the one accelerated part is the X.25 checksum, which it
computes with the fastcrc extension when that is installed (harness/requirements.txt pins it).
The script reports which checksum and parser are in use.
"""

import argparse
import json
import os
import statistics
import sys
import time

os.environ["MAVLINK20"] = "1"

import pymavlink  # noqa: E402
from pymavlink.dialects.v20 import ardupilotmega as mavlink  # noqa: E402

try:
    import pymavlink.mavnative  # noqa: F401  (absent from 2.4.50; kept in case a build provides it)
    NATIVE = "pymavlink.mavnative importable (but MAVLink.parse_buffer does not use it in this version)"
except ImportError:
    NATIVE = "none (pymavlink has no native parser in this version; use_native is ignored)"

CRC = "fastcrc (C extension)" if mavlink.x25crc.__name__ == "_x25crc_fast" else "pure Python"


def boundaries(data):
    """Frame offsets of a stream of unsigned MAVLink 2 frames, and its end."""
    out, p = [], 0
    while p < len(data):
        if data[p] != 0xFD or data[p + 2] & 0x01:
            raise SystemExit(f"not an unsigned MAVLink 2 frame at byte {p}")
        out.append(p)
        p += 12 + data[p + 1]
    if p != len(data):
        raise SystemExit("the last frame runs past the end of the stream")
    out.append(p)
    return out


def run_stream(data, chunk):
    mav = mavlink.MAVLink(None)
    n = 0
    names = {}
    t0 = time.perf_counter()
    for off in range(0, len(data), chunk):
        msgs = mav.parse_buffer(data[off:off + chunk])
        if msgs:
            n += len(msgs)
    elapsed = time.perf_counter() - t0
    return n, elapsed, mav


def run_datagrams(data, bounds):
    mav = mavlink.MAVLink(None)
    n = 0
    frames = [data[bounds[i]:bounds[i + 1]] for i in range(len(bounds) - 1)]
    t0 = time.perf_counter()
    for f in frames:
        msgs = mav.parse_buffer(f)
        if msgs:
            n += len(msgs)
    elapsed = time.perf_counter() - t0
    return n, elapsed, mav


def mix(data):
    """Message counts by name, from one decode of the whole stream (checks pymavlink agrees)."""
    mav = mavlink.MAVLink(None)
    counts = {}
    for m in mav.parse_buffer(data) or []:
        if m.get_type() == "BAD_DATA":
            raise SystemExit(f"pymavlink reported bad data: {m}")
        counts[m.get_type()] = counts.get(m.get_type(), 0) + 1
    return counts


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("file")
    ap.add_argument("--frames", type=int, help="frames the stream must hold (default: counted from the headers)")
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--chunk", type=int, default=4096)
    ap.add_argument("--json", action="store_true", help="one JSON object on stdout instead of text")
    a = ap.parse_args()

    with open(a.file, "rb") as f:
        data = f.read()
    bounds = boundaries(data)
    frames = len(bounds) - 1
    if a.frames is not None and frames != a.frames:
        raise SystemExit(f"{a.file} holds {frames} frames, expected {a.frames}")
    counts = mix(data)
    if sum(counts.values()) != frames:
        raise SystemExit(f"pymavlink decoded {sum(counts.values())} of {frames} frames")

    result = {
        "pymavlink": pymavlink.__version__ if hasattr(pymavlink, "__version__") else "?",
        "python": sys.version.split()[0],
        "crc": CRC,
        "native_parser": NATIVE,
        "frames": frames,
        "bytes": len(data),
        "mix": counts,
        "chunk": a.chunk,
        "repeat": a.repeat,
    }
    for mode in ("stream", "datagrams"):
        rates = []
        for _ in range(a.repeat):
            n, elapsed, mav = run_stream(data, a.chunk) if mode == "stream" else run_datagrams(data, bounds)
            if n != frames or mav.total_receive_errors:
                raise SystemExit(f"{mode}: parsed {n} of {frames} frames, {mav.total_receive_errors} errors")
            rates.append(frames / elapsed)
        result[mode] = {"best": max(rates), "median": statistics.median(rates), "all": rates}

    if a.json:
        print(json.dumps(result))
    else:
        print(f"pymavlink {result['pymavlink']} on Python {result['python']}; checksum: {CRC}; native parser: {NATIVE}")
        print(f"{frames} frames, {len(data)} bytes, {counts}")
        for mode in ("stream", "datagrams"):
            r = result[mode]
            print(f"{mode:10s} best {r['best']:12,.0f} frames/s   median {r['median']:12,.0f} frames/s   ({a.repeat} runs)")


if __name__ == "__main__":
    main()
