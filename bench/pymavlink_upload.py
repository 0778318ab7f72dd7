#!/usr/bin/env python3
"""The pymavlink reference for bench/ UploadBench: uploads missions to one simulated vehicle the
way MAVProxy's wp module does, and times each upload.

  pymavlink_upload.py --port-file FILE [--sysid 1] [--warmup 10] ITEMS.json...

Listens with the GroundStation of harness/gcs_session.py (mavutil udpin on 127.0.0.1, an
ephemeral port written to --port-file, replies to the address the vehicle sends from) and waits
for a heartbeat from --sysid. Each ITEMS.json (a list of [seq, command, frame, param1..4, x, y, z,
autocontinue], "nan" for NaN, as UploadBench writes them) goes into a mavwp.MAVWPLoader (not
timed). After --warmup untimed uploads of the second file (the first if only one) it prints
"ready" and then serves stdin, one line at a time, so that UploadBench can interleave its uploads
with ours under the same conditions:
  N     uploads the mission of N items and prints its time in ms ("fail ACK" if it failed): MISSION_COUNT,
        then every MISSION_REQUEST / MISSION_REQUEST_INT answered with the loader's MISSION_ITEM_INT
        for that seq (MAVProxy with wp_use_mission_int), until MISSION_ACK; the time runs from
        sending MISSION_COUNT to receiving the ACK;
  quit  prints one JSON document {"pymavlink", "python", "uploads": {N: [ms, ...]}, "errors"} and exits.
"""

import argparse
import json
import os
import platform
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "harness"))

from gcs_session import GroundStation, mavlink  # noqa: E402
from pymavlink import mavwp  # noqa: E402
import pymavlink  # noqa: E402


def loader_for(sysid, rows):
    loader = mavwp.MAVWPLoader(target_system=sysid, target_component=mavlink.MAV_COMP_ID_AUTOPILOT1)
    for r in rows:
        seq, command, frame, p1, p2, p3, p4, x, y, z, autocontinue = [float("nan") if v == "nan" else v for v in r]
        loader.add(mavlink.MAVLink_mission_item_int_message(
            sysid, mavlink.MAV_COMP_ID_AUTOPILOT1, int(seq), int(frame), int(command), 0, int(autocontinue),
            p1, p2, p3, p4, int(x), int(y), z, mavlink.MAV_MISSION_TYPE_MISSION))
    return loader


class Uploader(GroundStation):
    def __init__(self, port, deadline):
        GroundStation.__init__(self, port, deadline)
        self.handler = None

    def observe(self, m, address):
        GroundStation.observe(self, m, address)
        if self.handler is not None:
            self.handler(m)


def upload(gs, sysid, loader, timeout):
    state = {"ack": None}

    def handle(m):
        if m.get_srcSystem() != sysid:
            return
        kind = m.get_type()
        if kind in ("MISSION_REQUEST", "MISSION_REQUEST_INT"):
            w = loader.wp(m.seq)
            w.target_system = sysid
            w.target_component = mavlink.MAV_COMP_ID_AUTOPILOT1
            gs.send(sysid, w)
        elif kind == "MISSION_ACK":
            state["ack"] = m.type

    gs.handler = handle
    t0 = time.perf_counter()
    gs.send(sysid, gs.master.mav.mission_count_encode(sysid, mavlink.MAV_COMP_ID_AUTOPILOT1, loader.count(),
                                                      mavlink.MAV_MISSION_TYPE_MISSION))
    ok = gs.wait_until(lambda: state["ack"] is not None, timeout, "the MISSION_ACK of %d items" % loader.count())
    t1 = time.perf_counter()
    gs.handler = None
    return (t1 - t0) * 1000.0 if ok else None, state["ack"]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--port-file", required=True)
    p.add_argument("--sysid", type=int, default=1)
    p.add_argument("--warmup", type=int, default=10)
    p.add_argument("--deadline", type=float, default=600)
    p.add_argument("items", nargs="+")
    args = p.parse_args()
    gs = Uploader(0, args.deadline)
    tmp = args.port_file + ".tmp"
    with open(tmp, "w") as f:
        f.write("%d\n" % gs.local_port())
    os.replace(tmp, args.port_file)
    report = {"pymavlink": getattr(pymavlink, "__version__", "?"), "python": platform.python_version(),
              "uploads": {}, "errors": gs.errors}
    try:
        if not gs.wait_until(lambda: gs.heartbeats.get(args.sysid), 20, "a heartbeat from %d" % args.sysid):
            print("fail no heartbeat", flush=True)
            return
        missions = {}
        for path in args.items:
            with open(path) as f:
                rows = json.load(f)
            missions[len(rows)] = loader_for(args.sysid, rows)
        sizes = list(missions)
        for _ in range(args.warmup):
            upload(gs, args.sysid, missions[sizes[min(1, len(sizes) - 1)]], 10)
        print("ready", flush=True)
        for line in sys.stdin:
            line = line.strip()
            if line == "quit":
                break
            n = int(line)
            ms, ack = upload(gs, args.sysid, missions[n], 30)
            if ms is not None and ack == mavlink.MAV_MISSION_ACCEPTED:
                report["uploads"].setdefault(str(n), []).append(round(ms, 3))
                print("%.3f" % ms, flush=True)
            else:
                gs.errors.append("upload of %d items: ack %s" % (n, ack))
                print("fail ACK %s" % ack, flush=True)
    finally:
        gs.master.close()
    print(json.dumps(report), flush=True)


if __name__ == "__main__":
    main()
