#!/usr/bin/env python3
"""A pymavlink ground station flies a mission on one simulated vehicle the way MAVProxy does
(MissionSessionSpec). Tests only: an independent peer for dolphin.sim's mission protocol.

  mission_session.py --sysid 1 --home LAT,LON,ALT [--port 0] [--port-file FILE] [--deadline 60]

  Listens like gcs_session.py (one udpin socket, replies to the address each vehicle sends from;
  the GroundStation class is reused). Then, each step bounded by the deadline:
    1. waits for a heartbeat from the vehicle;
    2. builds a mission in a mavwp.MAVWPLoader (seq 0 a placeholder for home, 1 NAV_TAKEOFF 5 m,
       2 DO_CHANGE_SPEED 5 m/s, 3 and 4 NAV_WAYPOINT 20 m north and 20 m north-east at 5 m, 5 NAV_LAND
       there; MISSION_ITEM_INT in MAV_FRAME_GLOBAL_RELATIVE_ALT_INT) and uploads it: MISSION_COUNT,
       then every MISSION_REQUEST or MISSION_REQUEST_INT is answered with the loader's
       MISSION_ITEM_INT for that seq (as MAVProxy does with wp_use_mission_int), until MISSION_ACK;
    3. downloads it back: MISSION_REQUEST_LIST, MISSION_COUNT, then MISSION_REQUEST_INT for each seq
       (asked again after 1 s), MISSION_ITEM_INT, and the final MISSION_ACK; compares it with the
       upload field by field (seq 0 excepted, which the vehicle replaces with home);
    4. starts it as a copter needs: DO_SET_MODE GUIDED, arm, MAV_CMD_MISSION_START (0, 0);
    5. waits until the landing is over as ArduCopter ends it: the NAV_LAND current, then a heartbeat
       showing the vehicle disarmed after MISSION_CURRENT went back to the first item (a copter
       disarmed in AUTO starts its mission over; the landing is never reached nor the mission
       COMPLETE).
  Prints one JSON document with what it saw; a step that times out is listed in "errors".
"""

import argparse
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from gcs_session import GroundStation, mavlink  # noqa: E402
from pymavlink import mavwp  # noqa: E402

COPTER_GUIDED = 4
FIELDS = ["seq", "command", "frame", "param1", "param2", "param3", "param4", "x", "y", "z", "autocontinue"]


class MissionStation(GroundStation):
    """The GroundStation of gcs_session.py, keeping every message from the vehicle in order."""

    def __init__(self, port, deadline):
        GroundStation.__init__(self, port, deadline)
        self.log = []   # (t, sysid, message)

    def observe(self, m, address):
        GroundStation.observe(self, m, address)
        if m.get_type() != "BAD_DATA":
            self.log.append((self.now(), m.get_srcSystem(), m))

    def messages(self, sysid, since, kinds):
        return [m for _, s, m in self.log[since:] if s == sysid and m.get_type() in kinds]


def offset(lat, lon, north, east):
    r = 6378137.0
    return (lat + math.degrees(north / r), lon + math.degrees(east / (r * math.cos(math.radians(lat)))))


def item(sysid, seq, command, frame, params, lat, lon, alt):
    return mavlink.MAVLink_mission_item_int_message(
        sysid, mavlink.MAV_COMP_ID_AUTOPILOT1, seq, frame, command, 0, 1,
        params[0], params[1], params[2], params[3], int(round(lat * 1e7)), int(round(lon * 1e7)), alt,
        mavlink.MAV_MISSION_TYPE_MISSION)


def build(sysid, home):
    lat, lon, alt = home
    rel = mavlink.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT
    a = offset(lat, lon, 20, 0)
    b = offset(lat, lon, 20, 20)
    loader = mavwp.MAVWPLoader(target_system=sysid, target_component=mavlink.MAV_COMP_ID_AUTOPILOT1)
    loader.add(item(sysid, 0, mavlink.MAV_CMD_NAV_WAYPOINT, mavlink.MAV_FRAME_GLOBAL_INT, [0, 0, 0, 0], lat, lon, alt))
    loader.add(item(sysid, 1, mavlink.MAV_CMD_NAV_TAKEOFF, rel, [0, 0, 0, 0], lat, lon, 5))
    loader.add(item(sysid, 2, mavlink.MAV_CMD_DO_CHANGE_SPEED, mavlink.MAV_FRAME_MISSION, [1, 5, -1, 0], 0, 0, 0))
    loader.add(item(sysid, 3, mavlink.MAV_CMD_NAV_WAYPOINT, rel, [0, 0, 0, 0], a[0], a[1], 5))
    loader.add(item(sysid, 4, mavlink.MAV_CMD_NAV_WAYPOINT, rel, [0, 0, 0, 0], b[0], b[1], 5))
    loader.add(item(sysid, 5, mavlink.MAV_CMD_NAV_LAND, rel, [0, 0, 0, 0], b[0], b[1], 0))
    return loader


def fields(m):
    return {f: getattr(m, f) for f in FIELDS}


def as_reported(item):
    """An uploaded item of build()'s as ArduPilot reports it on download: the frame reduced to its
    altitude reference (GLOBAL, GLOBAL_RELATIVE_ALT or GLOBAL_TERRAIN_ALT), as AP_Mission stores it,
    and a NAV_LAND's param4 (its yaw direction, kept as a sign) 1 unless it was negative."""
    reference = {mavlink.MAV_FRAME_GLOBAL_RELATIVE_ALT: mavlink.MAV_FRAME_GLOBAL_RELATIVE_ALT,
                 mavlink.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT: mavlink.MAV_FRAME_GLOBAL_RELATIVE_ALT,
                 mavlink.MAV_FRAME_GLOBAL_TERRAIN_ALT: mavlink.MAV_FRAME_GLOBAL_TERRAIN_ALT,
                 mavlink.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT: mavlink.MAV_FRAME_GLOBAL_TERRAIN_ALT}
    reported = dict(item, frame=reference.get(item["frame"], mavlink.MAV_FRAME_GLOBAL))
    if item["command"] == mavlink.MAV_CMD_NAV_LAND:
        reported["param4"] = -1.0 if item["param4"] < 0 else 1.0
    return reported


def upload(gs, sysid, loader, report):
    start = len(gs.log)
    gs.send(sysid, gs.master.mav.mission_count_encode(sysid, mavlink.MAV_COMP_ID_AUTOPILOT1, loader.count(),
                                                      mavlink.MAV_MISSION_TYPE_MISSION))
    requests = []
    state = {"seen": start, "ack": None}

    def done():
        for _, s, m in gs.log[state["seen"]:]:
            if s != sysid:
                continue
            kind = m.get_type()
            if kind in ("MISSION_REQUEST", "MISSION_REQUEST_INT"):
                requests.append([kind, m.seq])
                w = loader.wp(m.seq)
                w.target_system = sysid
                w.target_component = mavlink.MAV_COMP_ID_AUTOPILOT1
                gs.send(sysid, w)
            elif kind == "MISSION_ACK":
                state["ack"] = m.type
        state["seen"] = len(gs.log)
        return state["ack"] is not None

    gs.wait_until(done, 15, "the upload's MISSION_ACK")
    report["upload"] = {"requests": requests, "ack": state["ack"],
                        "texts": [t for _, s, _, t in gs.texts if s == sysid]}


def download(gs, sysid, loader, report):
    start = len(gs.log)
    gs.send(sysid, gs.master.mav.mission_request_list_encode(sysid, mavlink.MAV_COMP_ID_AUTOPILOT1,
                                                             mavlink.MAV_MISSION_TYPE_MISSION))
    if not gs.wait_until(lambda: gs.messages(sysid, start, ["MISSION_COUNT"]), 5, "MISSION_COUNT"):
        return
    count = gs.messages(sysid, start, ["MISSION_COUNT"])[0].count
    items = []
    for seq in range(count):
        mark = len(gs.log)
        got = []

        def arrived():
            got[:] = [m for m in gs.messages(sysid, mark, ["MISSION_ITEM_INT"]) if m.seq == seq]
            return bool(got)

        for _ in range(5):
            gs.send(sysid, gs.master.mav.mission_request_int_encode(sysid, mavlink.MAV_COMP_ID_AUTOPILOT1, seq,
                                                                    mavlink.MAV_MISSION_TYPE_MISSION))
            if gs.wait_until(arrived, 1.0, "MISSION_ITEM_INT %d" % seq):
                gs.errors[:] = [e for e in gs.errors if "MISSION_ITEM_INT %d" % seq not in e]
                break
        if not got:
            return
        items.append(fields(got[0]))
    gs.send(sysid, gs.master.mav.mission_ack_encode(sysid, mavlink.MAV_COMP_ID_AUTOPILOT1,
                                                    mavlink.MAV_MISSION_ACCEPTED, mavlink.MAV_MISSION_TYPE_MISSION))
    uploaded = [as_reported(fields(loader.wp(i))) for i in range(loader.count())]
    report["download"] = {"count": count, "items": items,
                          "equal_except_home": items[1:] == uploaded[1:],
                          "differences": [[u, d] for u, d in zip(uploaded[1:], items[1:]) if u != d]}


def fly(gs, sysid, report):
    start = len(gs.log)
    results = {}
    for name, command, params in [
            ("guided", mavlink.MAV_CMD_DO_SET_MODE, [mavlink.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED, COPTER_GUIDED]),
            ("arm", mavlink.MAV_CMD_COMPONENT_ARM_DISARM, [1]),
            ("mission_start", mavlink.MAV_CMD_MISSION_START, [0, 0])]:
        results[name] = gs.command([sysid], command, params, 10, name)[sysid]["result"]

    def finished():
        seqs = [m.seq for m in gs.messages(sysid, start, ["MISSION_CURRENT"])]
        hbs = gs.messages(sysid, start, ["HEARTBEAT"])
        landing = seqs.index(5) if 5 in seqs else None
        restarted = landing is not None and 1 in seqs[landing:]
        disarmed = hbs and not hbs[-1].base_mode & mavlink.MAV_MODE_FLAG_SAFETY_ARMED
        return restarted and bool(disarmed)

    gs.wait_until(finished, 45, "the landing current, then the mission back at item 1 and a disarmed heartbeat")
    current = gs.messages(sysid, start, ["MISSION_CURRENT"])
    report["flight"] = {
        "commands": results,
        "reached": [m.seq for m in gs.messages(sysid, start, ["MISSION_ITEM_REACHED"])],
        "current": [[m.seq, m.total, m.mission_state] for m in current],
        "last_heartbeat_armed": bool(gs.heartbeats[sysid][-1][1].base_mode & mavlink.MAV_MODE_FLAG_SAFETY_ARMED),
        "last_custom_mode": gs.heartbeats[sysid][-1][1].custom_mode,
        "texts": [t for _, s, _, t in gs.texts if s == sysid],
    }


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--sysid", type=int, default=1)
    p.add_argument("--home", required=True, help="LAT,LON,ALT of the vehicle's home (degrees, metres AMSL)")
    p.add_argument("--port", type=int, default=0)
    p.add_argument("--port-file")
    p.add_argument("--deadline", type=float, default=60)
    args = p.parse_args()
    home = [float(v) for v in args.home.split(",")]
    gs = MissionStation(args.port, args.deadline)
    if args.port_file:
        tmp = args.port_file + ".tmp"
        with open(tmp, "w") as f:
            f.write("%d\n" % gs.local_port())
        os.replace(tmp, args.port_file)
    report = {"errors": gs.errors}
    try:
        if gs.wait_until(lambda: gs.heartbeats.get(args.sysid), 15, "a heartbeat from %d" % args.sysid):
            loader = build(args.sysid, home)
            upload(gs, args.sysid, loader, report)
            download(gs, args.sysid, loader, report)
            fly(gs, args.sysid, report)
    finally:
        gs.master.close()
    report["elapsed"] = round(gs.now(), 6)
    print(json.dumps(report, sort_keys=True))


if __name__ == "__main__":
    main()
