#!/usr/bin/env python3
"""The reference of bench/ LossyUploadBench: uploads missions to one simulated vehicle as MAVProxy's
`wp load` does, with pymavlink, and reports how each upload went.

  mavproxy_wpload.py --port-file FILE [--sysid 1]

Listens with the Uploader of pymavlink_upload.py (harness/gcs_session.py's GroundStation: mavutil
udpin on 127.0.0.1, an ephemeral port written to --port-file), waits for a heartbeat from --sysid,
prints "ready" and then serves stdin, one line at a time, pumping the socket all along:

  upload ITEMS.json DEADLINE
      ITEMS.json as UploadBench.itemsJson writes it, loaded into a mavwp.MAVWPLoader (not timed).
      Then what MAVProxy's wp module does (mission_item_protocol.py, wp_use_mission_int):
      MISSION_COUNT once, never sent again; each MISSION_REQUEST / MISSION_REQUEST_INT answered
      with that item as MISSION_ITEM_INT, but only while loading and at most 10 s after the
      MISSION_COUNT or the last request answered (after that MAVProxy stops loading and ignores
      requests); loading ends when the last item is sent, which is when MAVProxy reports the
      upload done: it does not wait for the MISSION_ACK. Prints one JSON line:
        {"outcome": "done" | "not done" | "abandoned" | "cancelled", "ms": COUNT to the last item
         sent (null unless done), "sent": items sent, "resends": items sent again (answers to the
         vehicle's repeated requests), "requests": requests heard, "detail": why not done}
      "not done": DEADLINE seconds passed; "abandoned": 10 s without a request, so MAVProxy would
      never answer again; "cancelled": the vehicle ended the upload with an error MISSION_ACK
      (OPERATION_CANCELLED after its 8 s without an item), after which it asks for nothing more.
  ack
      {"ack": the type of the first MISSION_ACK other than INVALID_SEQUENCE heard since the last
       upload's MISSION_COUNT, or null, "ack_ms": when, in ms since the MISSION_COUNT}
      (the bench asks once the vehicle has finished with the upload: MAVProxy never waits for it,
       this only records whether and when it came).
  quit
      {"pymavlink", "python"}, then exits.
"""

import argparse
import json
import os
import platform
import select
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from pymavlink_upload import Uploader, loader_for, mavlink  # noqa: E402
import pymavlink  # noqa: E402

REQUESTS = ("MISSION_REQUEST", "MISSION_REQUEST_INT")
QUIET_SECONDS = 10.0  # MAVProxy's loading_waypoint_lasttime + 10


class WpLoad:
    """One upload, fed the vehicle's messages as they come."""

    def __init__(self, gs, sysid, loader):
        self.gs = gs
        self.sysid = sysid
        self.loader = loader
        self.sent = {}
        self.requests = 0
        self.loading = True
        self.done_at = None
        self.cancelled = None
        self.ack = None
        self.ack_at = None
        self.start = time.perf_counter()
        self.last = self.start
        gs.send(sysid, gs.master.mav.mission_count_encode(sysid, mavlink.MAV_COMP_ID_AUTOPILOT1, loader.count(),
                                                          mavlink.MAV_MISSION_TYPE_MISSION))

    def handle(self, m):
        if m.get_srcSystem() != self.sysid or getattr(m, "mission_type", 0) != mavlink.MAV_MISSION_TYPE_MISSION:
            return
        now = time.perf_counter()
        kind = m.get_type()
        if kind in REQUESTS:
            self.requests += 1
            if not self.loading or now > self.last + QUIET_SECONDS:
                self.loading = False
                return
            if m.seq >= self.loader.count():
                return
            w = self.loader.wp(m.seq)
            w.target_system = self.sysid
            w.target_component = mavlink.MAV_COMP_ID_AUTOPILOT1
            self.gs.send(self.sysid, w)
            self.sent[m.seq] = self.sent.get(m.seq, 0) + 1
            self.last = now
            if m.seq == self.loader.count() - 1:
                self.loading = False
                self.done_at = now
        elif kind == "MISSION_ACK" and m.type != mavlink.MAV_MISSION_INVALID_SEQUENCE and self.ack is None:
            self.ack = m.type
            self.ack_at = now
            if self.done_at is None and m.type != mavlink.MAV_MISSION_ACCEPTED:
                self.loading = False
                self.cancelled = m.type

    def finished(self, deadline):
        """None while the upload goes on, else its outcome and why."""
        now = time.perf_counter()
        if self.done_at is not None:
            return "done", ""
        if self.cancelled is not None:
            return "cancelled", "MISSION_ACK %s" % mavlink.enums["MAV_MISSION_RESULT"][self.cancelled].name
        if not self.loading or now > self.last + QUIET_SECONDS:
            return "abandoned", "no request for %.0f s after %d of %d items" % (QUIET_SECONDS, len(self.sent),
                                                                                 self.loader.count())
        if now > self.start + deadline:
            return "not done", "not done in %.0f s (%d of %d items sent)" % (deadline, len(self.sent),
                                                                             self.loader.count())
        return None

    def report(self, outcome, detail):
        return {"outcome": outcome, "ms": None if self.done_at is None else round((self.done_at - self.start) * 1000, 3),
                "sent": sum(self.sent.values()), "resends": sum(self.sent.values()) - len(self.sent),
                "requests": self.requests, "detail": detail}

    def ack_report(self):
        return {"ack": self.ack, "ack_ms": None if self.ack_at is None else round((self.ack_at - self.start) * 1000, 3)}


def reply(obj):
    print(json.dumps(obj), flush=True)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--port-file", required=True)
    p.add_argument("--sysid", type=int, default=1)
    args = p.parse_args()
    gs = Uploader(0, 1e9)
    tmp = args.port_file + ".tmp"
    with open(tmp, "w") as f:
        f.write("%d\n" % gs.local_port())
    os.replace(tmp, args.port_file)
    current = None
    try:
        if not gs.wait_until(lambda: gs.heartbeats.get(args.sysid), 30, "a heartbeat from %d" % args.sysid):
            print("fail no heartbeat", flush=True)
            return
        print("ready", flush=True)
        while True:
            readable, _, _ = select.select([gs.sock, sys.stdin], [], [])
            if gs.sock in readable:
                gs.pump(0)
            if sys.stdin not in readable:
                continue
            words = sys.stdin.readline().split()
            if not words or words[0] == "quit":
                break
            if words[0] == "ack":
                reply(current.ack_report() if current else {"ack": None, "ack_ms": None})
                continue
            with open(words[1]) as f:
                loader = loader_for(args.sysid, json.load(f))
            current = WpLoad(gs, args.sysid, loader)
            gs.handler = current.handle
            while True:
                outcome = current.finished(float(words[2]))
                if outcome is not None:
                    break
                gs.pump(0.05)
            current.loading = False  # stopped at the deadline too: no more answers, as after MAVProxy's 10 s
            reply(current.report(*outcome))
    finally:
        gs.master.close()
    reply({"pymavlink": getattr(pymavlink, "__version__", "?"), "python": platform.python_version()})


if __name__ == "__main__":
    main()
