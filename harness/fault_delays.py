#!/usr/bin/env python3
"""Measures, for a recording of harness/sitl-faults.sh, how long dolphin's script took to hear of a fault.

    .venv/bin/python harness/fault_delays.py src/test/resources/sitl-recordings/copter-fault-motor
    .venv/bin/python harness/fault_delays.py src/test/resources/sitl-recordings/copter-fault-stall 40.444233,-7.3749983

Reads NAME.faults.txt (the injection's wall time), NAME.tlog (what the vehicle sent, as dolphin received
it, with Unix-time stamps) and NAME.out (dolphin's lines, each prefixed with the wall clock it was read
at). Prints the vehicle's signs after the injection (STATUSTEXT at WARNING or worse, changes of mode or
arming, of landed state), the first of them, dolphin's first lines that report the fault (onError,
"taken over", "back in AUTO", "no progress", contact), and each one's delay from the first sign on the
wall clock and on the vehicle's clock (time since boot: the last time_boot_ms dolphin had received
before that moment).
"""
import datetime
import math
import os
import re
import sys

os.environ["MAVLINK20"] = "1"
from pymavlink import mavutil  # noqa: E402

SEVERITY = ["EMERGENCY", "ALERT", "CRITICAL", "ERROR", "WARNING", "NOTICE", "INFO", "DEBUG"]
LANDED = ["UNDEFINED", "ON_GROUND", "IN_AIR", "TAKEOFF", "LANDING"]
REPORTS = re.compile(r"onError|taken over|back in AUTO|no progress|stalled|no contact|contact again|lost|is back|fault survey:")
STATUS = re.compile(r"\] vehicle \d+: ([A-Z_]+|unknown), (armed|disarmed)|\] vehicle \d+: LOST, ")   # status lines
VEHICLE_TEXT = re.compile(r"\[(INFO|WARN|WARNING|ERROR)\] vehicle \d+: ")   # the vehicle's own words, relayed


def wall_of(clock, day):
    """HH:MM:SS.mmm on the day of the recording, as a Unix time."""
    t = datetime.datetime.strptime(clock, "%H:%M:%S.%f").time()
    return datetime.datetime.combine(day, t).timestamp()


def distance(lat1, lon1, lat2, lon2):
    """Metres between two points (equirectangular: a few km at most)."""
    x = math.radians(lon2 - lon1) * math.cos(math.radians((lat1 + lat2) / 2))
    return 6371000 * math.hypot(x, math.radians(lat2 - lat1))


def main(name, target=None):
    mlog = mavutil.mavlink_connection(name + ".tlog", dialect="ardupilotmega")
    frames = []   # (wall, boot, message) of the vehicle's frames
    boot = 0.0
    while True:
        m = mlog.recv_match()
        if m is None:
            break
        if m.get_type() == "BAD_DATA" or m.get_srcSystem() != 1:
            continue
        if hasattr(m, "time_boot_ms"):
            boot = m.time_boot_ms / 1000.0
        frames.append((m._timestamp, boot, m))
    day = datetime.date.fromtimestamp(frames[0][0])

    injected = None
    for line in open(name + ".faults.txt"):
        if " injection: " in line:
            injected = wall_of(line.split()[0], day)
            print("injection   %s" % line.strip())
            break
    if injected is None:
        sys.exit("no injection in %s.faults.txt" % name)

    def boot_at(wall):
        b = 0.0
        for w, fb, _ in frames:
            if w > wall:
                break
            b = fb
        return b

    signs = []
    mode = armed = landed = None
    for w, b, m in frames:
        t = m.get_type()
        what = None
        if t == "HEARTBEAT" and m.get_srcComponent() == 1:
            state = (m.custom_mode, bool(m.base_mode & 128))
            if (mode, armed) != state and mode is not None:
                what = "HEARTBEAT mode %d %s" % (state[0], "armed" if state[1] else "disarmed")
            mode, armed = state
        elif t == "EXTENDED_SYS_STATE":
            if landed is not None and m.landed_state != landed:
                what = "EXTENDED_SYS_STATE %s" % LANDED[m.landed_state]
            landed = m.landed_state
        elif t == "STATUSTEXT" and m.severity <= 4:
            what = "STATUSTEXT %s '%s'" % (SEVERITY[m.severity], m.text)
        if what and w >= injected:
            signs.append((w, b, what))
    print("vehicle's signs after the injection (wall s / boot s from the injection):")
    inj_boot = boot_at(injected)
    for w, b, what in signs[:12]:
        print("  +%7.3f / +%7.3f  %s" % (w - injected, b - inj_boot, what))
    # a stall says nothing: when did the vehicle last come 1 m closer to its waypoint (--target LAT,LON, at
    # the vehicle's height), which starts dolphin's stall clock?
    if target:
        closest = last_progress = None
        for w, b, m in frames:
            if m.get_type() == "GLOBAL_POSITION_INT" and w >= injected:
                d = distance(m.lat / 1e7, m.lon / 1e7, *target)
                if closest is None or d <= closest - 1:
                    closest, last_progress = d, (w, b)
        print("last progress +%.3f s wall, boot %.3f: %.0f m from the waypoint, the closest after the injection" % (
            last_progress[0] - injected, last_progress[1], closest))
        print("farthest %.0f m" % max(distance(m.lat / 1e7, m.lon / 1e7, *target) for w, b, m in frames
                                      if m.get_type() == "GLOBAL_POSITION_INT" and w >= injected))
    # an outage: the longest silence in what dolphin received after the injection
    after = [(w, b) for w, b, _ in frames if w >= injected - 1]
    gaps = [(after[i + 1][0] - after[i][0], after[i], after[i + 1]) for i in range(len(after) - 1)]
    if gaps:
        gap, before, back = max(gaps)
        if gap > 2:
            print("silence     %.3f s: last frame +%.3f s wall (boot %.3f), next +%.3f s wall (boot %.3f)" % (
                gap, before[0] - injected, before[1], back[0] - injected, back[1]))
    first = signs[0] if signs else None
    if first:
        print("first sign  +%.3f s wall, boot %.3f: %s" % (first[0] - injected, first[1], first[2]))
    seen = set()
    for line in open(name + ".out"):
        parts = line.rstrip("\n").split(" ", 1)
        if len(parts) < 2 or not re.match(r"\d\d:\d\d:\d\d\.\d{3}$", parts[0]):
            continue
        w = wall_of(parts[0], day)
        text = parts[1]
        key = REPORTS.search(text)
        if (w < injected or not key or key.group(0) in seen or "task fault survey" in text
                or VEHICLE_TEXT.search(text) or STATUS.search(text)):
            continue
        seen.add(key.group(0))
        ref = first if first else (injected, inj_boot, "injection")
        print("dolphin     +%.3f s wall, +%.3f s boot after the %s: %s" % (
            w - ref[0], boot_at(w) - ref[1], "first sign" if first else "injection", text.strip()))


if __name__ == "__main__":
    main(sys.argv[1].removesuffix(".tlog"), tuple(map(float, sys.argv[2].split(","))) if len(sys.argv) > 2 else None)
