#!/usr/bin/env python3
"""pymavlink's side of the frame codec interoperability test (CodecInteropSpec).

Tests only: an independent MAVLink implementation to check dolphin.mavlink.codec against.

  codec_interop.py encode --seed N --key HEX64 --link-id L --timestamp T
      For every message the runtime and the simulator use, builds messages with seeded
      pseudo-random field values and prints one JSON object per line:
        {"kind": "v2" | "signed" | "v1", "variant", "name", "msgid", "version", "seq", "sysid",
         "compid", "hex", "fields", and for signed frames "linkId" and "timestamp"}
      kind v2: MAVLink 2, unsigned, four variants per message (min, max, random-0, random-1;
               random-0 keeps uint64 values below 2^63, which the generated Java classes can write);
      kind signed: MAVLink 2 signed with the key, link id, and timestamps T, T+1, ... in order;
      kind v1: MAVLink 1 (pymavlink's force_mavlink1, which keeps the extension fields).

  codec_interop.py decode [--key HEX64]
      Reads one frame per line, in hex, from stdin and prints one JSON object per line:
        {"ok": true, "name", "msgid", "version", "seq", "sysid", "compid", "incompat", "len",
         "signed": the frame carries a signature, "sigOk": it verified with the key,
         "linkId", "timestamp", "fields"}
      or {"ok": false, "line", "error"} for a line that is not exactly one good frame. With a
      key, unsigned and wrongly signed frames are still decoded (sigOk false).

With DOLPHIN_MAVLINK_DIALECT set to a directory, its ardupilotmega.py (mavgen's Python output) is the
dialect, as CodecInteropSpec gives the build's; else pymavlink's own.

"fields" are pymavlink's to_dict() values (char arrays as strings, arrays as lists), except that
non-finite floats, which JSON cannot carry, are the strings "NaN", "Infinity" and "-Infinity".
Floats are float32 values, printed exactly (Python's shortest repr of the double, -0.0 included).
"""

import argparse
import json
import math
import os
import random
import struct
import sys

os.environ["MAVLINK20"] = "1"

# The definitions the runtime's bindings are generated from (harness/generate-bindings.sh: pymavlink's
# with MAVLink's plan-id fields), when their Python module's directory is given; else pymavlink's own.
if os.environ.get("DOLPHIN_MAVLINK_DIALECT"):
    sys.path.insert(0, os.environ["DOLPHIN_MAVLINK_DIALECT"])
    import ardupilotmega as mavlink  # noqa: E402
else:
    from pymavlink.dialects.v20 import ardupilotmega as mavlink  # noqa: E402

MESSAGES = [
    "HEARTBEAT", "SYS_STATUS", "GLOBAL_POSITION_INT", "STATUSTEXT", "COMMAND_LONG", "COMMAND_ACK",
    "SET_MODE", "MISSION_COUNT", "MISSION_REQUEST", "MISSION_REQUEST_INT", "MISSION_REQUEST_LIST",
    "MISSION_ITEM", "MISSION_ITEM_INT", "MISSION_ACK", "MISSION_CURRENT", "MISSION_ITEM_REACHED",
    "MISSION_CLEAR_ALL", "MISSION_SET_CURRENT", "EXTENDED_SYS_STATE", "BATTERY_STATUS",
    "HOME_POSITION", "REQUEST_DATA_STREAM", "AUTOPILOT_VERSION", "PARAM_VALUE",
]

INT_RANGES = {
    "uint8_t": (0, 2**8 - 1), "uint16_t": (0, 2**16 - 1), "uint32_t": (0, 2**32 - 1),
    "uint64_t": (0, 2**64 - 1), "int8_t": (-2**7, 2**7 - 1), "int16_t": (-2**15, 2**15 - 1),
    "int32_t": (-2**31, 2**31 - 1), "int64_t": (-2**63, 2**63 - 1),
}
FLOAT_MAX = struct.unpack("<f", b"\xff\xff\x7f\x7f")[0]
FLOAT_MIN_SUBNORMAL = struct.unpack("<f", b"\x01\x00\x00\x00")[0]
DOUBLE_MAX = sys.float_info.max
PRINTABLE = "".join(chr(c) for c in range(0x20, 0x7F))

BY_NAME = {cls.msgname: cls for cls in mavlink.mavlink_map.values()}


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def fields_of(cls):
    """(name, type, array length or 0) in declaration order."""
    out = []
    for i, name in enumerate(cls.fieldnames):
        out.append((name, cls.fieldtypes[i], cls.array_lengths[cls.ordered_fieldnames.index(name)]))
    return out


def scalar(rng, ftype, variant):
    if ftype in INT_RANGES:
        lo, hi = INT_RANGES[ftype]
        if ftype == "uint64_t" and variant == "random-0":
            hi = 2**63 - 1  # what the generated Java classes can write (a Java long); other variants use all 64 bits
        if variant == "min":
            return lo
        if variant == "max":
            return hi
        r = rng.random()
        if r < 0.15:
            return 0
        if r < 0.25:
            return rng.choice([lo, hi])
        if r < 0.4:
            return rng.randint(max(lo, -1000), min(hi, 1000))
        return rng.randint(lo, hi)
    if ftype in ("float", "double"):
        big = FLOAT_MAX if ftype == "float" else DOUBLE_MAX
        if variant == "min":
            return -big
        if variant == "max":
            return big
        r = rng.random()
        if r < 0.1:
            value = 0.0
        elif r < 0.17:
            value = math.nan
        elif r < 0.22:
            value = rng.choice([math.inf, -math.inf])
        elif r < 0.27:
            value = rng.choice([big, -big, FLOAT_MIN_SUBNORMAL, -FLOAT_MIN_SUBNORMAL, -0.0])
        elif r < 0.6:
            value = rng.uniform(-1000.0, 1000.0)
        else:
            value = math.ldexp(rng.uniform(-1.0, 1.0), rng.randint(-60, 60))
        return f32(value) if ftype == "float" else value
    raise ValueError("no generator for type " + ftype)


def text(rng, length, variant):
    if variant == "min":
        return b""
    if variant == "max":
        n = length
    else:
        n = rng.choice([0, 1, length, rng.randint(1, length)])
    return "".join(rng.choice(PRINTABLE) for _ in range(n)).encode("ascii")


def values(rng, cls, variant):
    kwargs = {}
    for name, ftype, length in fields_of(cls):
        if ftype == "char":
            kwargs[name] = text(rng, max(length, 1), variant)
        elif length:
            kwargs[name] = [scalar(rng, ftype, variant) for _ in range(length)]
        else:
            kwargs[name] = scalar(rng, ftype, variant)
    return kwargs


def jsonable(value):
    if isinstance(value, float) and not math.isfinite(value):
        return "NaN" if math.isnan(value) else ("Infinity" if value > 0 else "-Infinity")
    if isinstance(value, (list, tuple)):
        return [jsonable(v) for v in value]
    if isinstance(value, (bytes, bytearray)):
        return value.decode(errors="backslashreplace").rstrip("\x00")
    return value


def fields_json(msg):
    d = msg.to_dict()
    d.pop("mavpackettype", None)
    return {k: jsonable(v) for k, v in d.items()}


def emit(obj):
    sys.stdout.write(json.dumps(obj, allow_nan=False, separators=(",", ":")) + "\n")


def encode(args):
    rng = random.Random(args.seed)
    key = bytes.fromhex(args.key)
    if len(key) != 32:
        raise SystemExit("the signing key must be 32 bytes (64 hex digits)")
    timestamp = args.timestamp
    header_rng = random.Random(args.seed + 1)

    def header(variant):
        if variant == "min":
            return 0, 0, 0
        if variant == "max":
            return 255, 255, 255
        return header_rng.randint(0, 255), header_rng.randint(1, 255), header_rng.randint(0, 255)

    def pack(kind, variant, cls, kwargs, seq, sysid, compid):
        nonlocal timestamp
        msg = cls(**kwargs)
        mav = mavlink.MAVLink(None, srcSystem=sysid, srcComponent=compid)
        mav.seq = seq
        out = {"kind": kind, "variant": variant, "name": cls.msgname, "msgid": cls.id,
               "version": 1 if kind == "v1" else 2, "seq": seq, "sysid": sysid, "compid": compid}
        if kind == "signed":
            mav.signing.secret_key = key
            mav.signing.link_id = args.link_id
            mav.signing.timestamp = timestamp
            mav.signing.sign_outgoing = True
            out["linkId"] = args.link_id
            out["timestamp"] = timestamp
        frame = msg.pack(mav, force_mavlink1=(kind == "v1"))
        if kind == "signed":
            timestamp = mav.signing.timestamp
        out["hex"] = bytes(frame).hex()
        out["fields"] = fields_json(msg)
        emit(out)

    for name in MESSAGES:
        cls = BY_NAME[name]
        per_variant = {}
        for variant in ("min", "max", "random-0", "random-1"):
            per_variant[variant] = values(rng, cls, variant)
            seq, sysid, compid = header(variant)
            pack("v2", variant, cls, per_variant[variant], seq, sysid, compid)
        seq, sysid, compid = header("random")
        pack("signed", "random-0", cls, per_variant["random-0"], seq, sysid, compid)
        if cls.id < 256:
            seq, sysid, compid = header("random")
            pack("v1", "random-1", cls, per_variant["random-1"], seq, sysid, compid)


def decode_line(line, key):
    data = bytes.fromhex(line)
    mav = mavlink.MAVLink(None)
    mav.robust_parsing = True
    if key is not None:
        mav.signing.secret_key = key
        # Decode unsigned and wrongly signed frames as well and report sigOk false.
        mav.signing.allow_unsigned_callback = lambda _mav, _msgid: True
    msgs = mav.parse_buffer(data) or []
    bad = [m for m in msgs if m.get_type() == "BAD_DATA"]
    if bad:
        return {"ok": False, "error": "bad data: " + "; ".join(str(m.reason) for m in bad)}
    if mav.buf_len() != 0:
        return {"ok": False, "error": "%d bytes left over (incomplete frame)" % mav.buf_len()}
    if len(msgs) != 1:
        return {"ok": False, "error": "%d frames in one line" % len(msgs)}
    m = msgs[0]
    if m.get_type().startswith("UNKNOWN_"):
        return {"ok": False, "error": "unknown message id " + m.get_type()}
    buf = m.get_msgbuf()
    h = m.get_header()
    version = 1 if buf[0] == mavlink.PROTOCOL_MARKER_V1 else 2
    signed = version == 2 and (h.incompat_flags & mavlink.MAVLINK_IFLAG_SIGNED) != 0
    out = {"ok": True, "name": m.get_type(), "msgid": m.get_msgId(), "version": version,
           "seq": h.seq, "sysid": h.srcSystem, "compid": h.srcComponent,
           "incompat": h.incompat_flags, "len": h.mlen, "signed": signed,
           "sigOk": bool(m.get_signed())}
    if signed:
        out["linkId"] = buf[-13]
        out["timestamp"] = int.from_bytes(bytes(buf[-12:-6]), "little")
    out["fields"] = fields_json(m)
    return out


def decode(args):
    key = bytes.fromhex(args.key) if args.key else None
    for n, line in enumerate(sys.stdin):
        line = line.strip()
        try:
            out = decode_line(line, key)
        except Exception as e:  # a bad line must not stop the others
            out = {"ok": False, "error": "%s: %s" % (type(e).__name__, e)}
        out["line"] = n
        emit(out)
        sys.stdout.flush()


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = p.add_subparsers(dest="mode", required=True)
    e = sub.add_parser("encode")
    e.add_argument("--seed", type=int, default=1)
    e.add_argument("--key", required=True, help="signing key, 64 hex digits")
    e.add_argument("--link-id", type=int, default=0)
    e.add_argument("--timestamp", type=int, default=1, help="first signature timestamp (10 us since 2015)")
    d = sub.add_parser("decode")
    d.add_argument("--key", help="signing key, 64 hex digits, to verify signatures")
    args = p.parse_args()
    if args.mode == "encode":
        encode(args)
    else:
        decode(args)


if __name__ == "__main__":
    main()
