#!/usr/bin/env python3
"""A pymavlink ground station against our simulated vehicles, and pymavlink reading our .tlog
(PymavlinkGroundStationSpec). Tests only: an independent MAVLink peer to check dolphin.sim and
dolphin.mavlink against.

  gcs_session.py session --sysids 1,2,3 [--port 0] [--port-file FILE] [--deadline 60]
                         [--interval-us 200000]
      Listens with mavutil.mavlink_connection('udpin:127.0.0.1:PORT', source_system=255) (port 0:
      an ephemeral port, written to --port-file once bound, so the caller can point the vehicles
      at it without a race). Then, each step bounded by the deadline:
        1. waits for two heartbeats from every expected system id (so at least one heartbeat period
           is watched before anything is requested) and records type, autopilot, custom_mode;
        2. asks every vehicle for GLOBAL_POSITION_INT (33) and SYS_STATUS (1) with
           MAV_CMD_SET_MESSAGE_INTERVAL and waits for both to arrive; what arrived before the
           request is recorded, to show streams exist only when requested;
        3. arms every vehicle (MAV_CMD_COMPONENT_ARM_DISARM) and records the COMMAND_ACK result and
           the STATUSTEXTs the vehicle sent meanwhile (after a refusal, it waits for the text);
        4. sets GUIDED (copter custom mode 4) with MAV_CMD_DO_SET_MODE and waits for a heartbeat,
           received after the COMMAND_ACK, that shows it.
      Prints one JSON document with everything observed (see `report`); a step that times out is
      listed in "errors" and the session goes on, so the caller sees all it can; "mav_loss" is
      pymavlink's count of frames missing from the vehicles' sequence numbers. Exit status 0
      unless the script itself fails.

  gcs_session.py tlog FILE
      Reads a telemetry log with mavutil.mavlink_connection(FILE) and prints one JSON document:
        {"frames": messages read, "bad_data": BAD_DATA count, "indexed": frames pymavlink's mmap
         index counted, "by_sysid": {sysid: {type: count}}, "first_timestamp", "last_timestamp"
         (Unix seconds), "backwards": timestamps smaller than the one before, "seq_gaps": frames
         missing from each sender's (sysid, compid) sequence numbers, "reader": the mavutil class
         that read it}
      The gaps are counted here, not taken from pymavlink's mav_loss: mavmmaplog (what
      mavlink_connection opens a .tlog with) indexes the file first, reading the first message of
      each type out of order through post_message, which leaves mav_loss and last_seq polluted
      (hundreds of "lost" frames in a log with none missing).
"""

import argparse
import json
import os
import select
import sys
import time

os.environ["MAVLINK20"] = "1"

from pymavlink import mavutil  # noqa: E402

mavlink = mavutil.mavlink

GLOBAL_POSITION_INT = mavlink.MAVLINK_MSG_ID_GLOBAL_POSITION_INT
SYS_STATUS = mavlink.MAVLINK_MSG_ID_SYS_STATUS
STREAMS = [(GLOBAL_POSITION_INT, "GLOBAL_POSITION_INT"), (SYS_STATUS, "SYS_STATUS")]
COPTER_GUIDED = 4
RESEND_SECONDS = 1.0


class _Unicast:
    """What pymavlink's MAVLink.send writes to (its `file`): one datagram to one address."""

    def __init__(self, sock, address):
        self.sock = sock
        self.address = address

    def write(self, buf):
        self.sock.sendto(buf, self.address)


class GroundStation:
    """One udpin socket for the whole fleet, as MAVProxy or Mission Planner listen on 14550.

    Targeting: every simulated vehicle sends from its own UDP port (like SITL's
    --serial0 udpclient:HOST:PORT), all to our one port. mavudp in udpin mode remembers every
    sender in `clients` and its write() sends each datagram to *all* of them (pymavlink 2.4.50,
    udp_timeout 0; earlier releases replied to the last sender only, and `last_address` is kept
    only for udpbcast). Broadcasting works only because each vehicle drops commands whose
    target_system is not its own; MAVLink routing (ArduPilot's MAVLink_routing) instead learns
    which link and address each system id is heard on and sends targeted messages only there. This
    station does the same: it reads the socket itself, and each datagram's source
    address goes with the messages pymavlink's parser (mav.parse_buffer, all frames of the datagram)
    decodes from it, giving a map sysid -> address; mavutil's bookkeeping still runs (post_message:
    sysid_state, flight mode names, loss counts). Commands are built and sent by pymavlink's
    MAVLink.send (sequence numbers, counters) with its output pointed at that vehicle's address
    alone, and master.target_system is set to the vehicle addressed.
    """

    def __init__(self, port, deadline):
        self.master = mavutil.mavlink_connection("udpin:127.0.0.1:%d" % port, source_system=255)
        self.sock = self.master.port
        self.start = time.monotonic()
        self.deadline = self.start + deadline
        self.addresses = {}     # sysid -> (host, port) of the vehicle's socket
        self.counts = {}        # sysid -> {type: count}
        self.first_seen = {}    # sysid -> {type: seconds since start}
        self.heartbeats = {}    # sysid -> [(t, HEARTBEAT message)]
        self.acks = []          # (t, sysid, COMMAND_ACK message)
        self.texts = []         # (t, sysid, severity, text)
        self.errors = []

    def now(self):
        return time.monotonic() - self.start

    def local_port(self):
        return self.sock.getsockname()[1]

    # ---- receiving -----------------------------------------------------------------------------

    def pump(self, timeout):
        """Waits up to `timeout` seconds for datagrams and handles all that are there."""
        timeout = max(0.0, min(timeout, self.deadline - time.monotonic()))
        readable, _, _ = select.select([self.sock], [], [], timeout)
        if not readable:
            return
        while True:
            try:
                data, address = self.sock.recvfrom(65535)
            except (BlockingIOError, InterruptedError, ConnectionRefusedError):
                return
            for m in self.master.mav.parse_buffer(data) or []:
                self.master.post_message(m)
                self.observe(m, address)

    def observe(self, m, address):
        t = self.now()
        kind = m.get_type()
        sysid = m.get_srcSystem()
        if kind == "BAD_DATA":
            self.counts.setdefault("bad", {}).setdefault(kind, 0)
            self.counts["bad"][kind] += 1
            return
        if m.get_srcComponent() == mavlink.MAV_COMP_ID_AUTOPILOT1:
            self.addresses[sysid] = address
        self.counts.setdefault(sysid, {}).setdefault(kind, 0)
        self.counts[sysid][kind] += 1
        self.first_seen.setdefault(sysid, {}).setdefault(kind, round(t, 6))
        if kind == "HEARTBEAT":
            self.heartbeats.setdefault(sysid, []).append((t, m))
        elif kind == "COMMAND_ACK":
            self.acks.append((t, sysid, m))
        elif kind == "STATUSTEXT":
            self.texts.append((t, sysid, m.severity, m.text))

    def wait_until(self, condition, timeout, what):
        """Pumps until condition() holds; False (and an error recorded) after timeout seconds."""
        end = min(time.monotonic() + timeout, self.deadline)
        while not condition():
            left = end - time.monotonic()
            if left <= 0:
                self.errors.append("timed out after %.1f s waiting for %s" % (timeout, what))
                return False
            self.pump(min(left, 0.1))
        return True

    # ---- sending -------------------------------------------------------------------------------

    def send(self, sysid, msg):
        """Sends msg to one vehicle's address only (see the class comment)."""
        mav = self.master.mav
        self.master.target_system = sysid
        self.master.target_component = mavlink.MAV_COMP_ID_AUTOPILOT1
        previous = mav.file
        mav.file = _Unicast(self.sock, self.addresses[sysid])
        try:
            mav.send(msg)
        finally:
            mav.file = previous

    def command(self, sysids, command, params, timeout, what):
        """Sends a COMMAND_LONG to each vehicle, again every second (confirmation + 1) until its
        COMMAND_ACK for that command arrives. Returns {sysid: {"result", "sent", "acked",
        "attempts", "target_system"}}; vehicles that never answered have result None."""
        out = {}
        for s in sysids:
            out[s] = {"result": None, "sent": None, "acked": None, "attempts": 0, "target_system": None}
        pending = set(sysids)
        seen = len(self.acks)

        def send(s):
            rec = out[s]
            msg = self.master.mav.command_long_encode(s, mavlink.MAV_COMP_ID_AUTOPILOT1, command,
                                                      rec["attempts"], *(list(params) + [0] * 7)[:7])
            self.send(s, msg)
            if rec["sent"] is None:
                rec["sent"] = round(self.now(), 6)
            rec["attempts"] += 1
            rec["last"] = time.monotonic()

        for s in sysids:
            send(s)

        def done():
            nonlocal seen
            for t, s, ack in self.acks[seen:]:
                if s in pending and ack.command == command:
                    pending.discard(s)
                    out[s].update(result=ack.result, acked=round(t, 6), target_system=ack.target_system)
            seen = len(self.acks)
            for s in pending:
                if time.monotonic() - out[s]["last"] >= RESEND_SECONDS:
                    send(s)
            return not pending

        self.wait_until(done, timeout, "COMMAND_ACK of %s from %s" % (what, sorted(pending)))
        for rec in out.values():
            rec.pop("last", None)
        return out

    def texts_from(self, sysid, since):
        return [{"t": round(t, 6), "severity": sev, "text": text}
                for t, s, sev, text in self.texts if s == sysid and t >= since]

    # ---- the session ---------------------------------------------------------------------------

    def session(self, sysids, interval_us):
        report = {"port": self.local_port(), "sysids": sysids, "vehicles": {}, "errors": self.errors}
        vehicles = report["vehicles"]

        # 1. heartbeats: two from each, so at least a heartbeat period is watched before requests
        self.wait_until(lambda: all(len(self.heartbeats.get(s, [])) >= 2 for s in sysids), 15,
                        "two heartbeats from each of %s" % sysids)
        present = [s for s in sysids if self.heartbeats.get(s)]
        for s in sysids:
            v = vehicles.setdefault(str(s), {})
            hbs = self.heartbeats.get(s, [])
            if hbs:
                t, hb = hbs[0]
                v["heartbeat"] = {"t": round(t, 6), "type": hb.type, "autopilot": hb.autopilot,
                                  "base_mode": hb.base_mode, "custom_mode": hb.custom_mode,
                                  "system_status": hb.system_status, "mavlink_version": hb.mavlink_version,
                                  "count": len(hbs)}
                v["address"] = list(self.addresses[s])
                v["frame_magic"] = hb.get_msgbuf()[0]  # 0xFD (253): MAVLink 2
        ids = present

        # 2. streams, requested at interval_us each; what came before the request is kept
        for s in ids:
            vehicles[str(s)]["before_request"] = dict(self.counts.get(s, {}))
        requests = {}
        for msgid, name in STREAMS:
            requests[name] = self.command(ids, mavlink.MAV_CMD_SET_MESSAGE_INTERVAL, [msgid, interval_us], 10,
                                          "SET_MESSAGE_INTERVAL %s" % name)
        self.wait_until(lambda: all(self.counts.get(s, {}).get(name, 0) > 0 for s in ids for _, name in STREAMS), 10,
                        "GLOBAL_POSITION_INT and SYS_STATUS from each of %s" % ids)
        for s in ids:
            v = vehicles[str(s)]
            v["streams"] = {}
            for _, name in STREAMS:
                st = dict(requests[name][s])
                st["first_received"] = self.first_seen.get(s, {}).get(name)
                st["count"] = self.counts.get(s, {}).get(name, 0)
                v["streams"][name] = st
            pos = self.master.sysid_state[s].messages.get("GLOBAL_POSITION_INT")
            if pos is not None:
                v["position"] = {"lat": pos.lat, "lon": pos.lon, "alt": pos.alt, "relative_alt": pos.relative_alt}
            status = self.master.sysid_state[s].messages.get("SYS_STATUS")
            if status is not None:
                v["battery_remaining"] = status.battery_remaining

        # 3. arm; wait (bounded) for the STATUSTEXT that says why after a refusal, or "Arming motors"
        # after an ACCEPTED: ArduCopter sends it after its COMMAND_ACK, so it may come a moment later
        arm = self.command(ids, mavlink.MAV_CMD_COMPONENT_ARM_DISARM, [1], 10, "arm")
        answered = [s for s in ids if arm[s]["result"] is not None]
        self.wait_until(lambda: all(self.texts_from(s, arm[s]["sent"]) for s in answered), 3,
                        "a STATUSTEXT from each vehicle that answered the arm command: %s" % answered)
        for s in ids:
            rec = dict(arm[s])
            rec["statustext"] = self.texts_from(s, arm[s]["sent"]) if arm[s]["sent"] is not None else []
            vehicles[str(s)]["arm"] = rec

        # 4. GUIDED, confirmed by a heartbeat received after the COMMAND_ACK
        mode = self.command(ids, mavlink.MAV_CMD_DO_SET_MODE,
                            [mavlink.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED, COPTER_GUIDED], 10, "DO_SET_MODE GUIDED")

        def guided_heartbeat(s):
            if mode[s]["acked"] is None:
                return None
            return next((hb for t, hb in self.heartbeats.get(s, [])
                         if t >= mode[s]["acked"] and hb.custom_mode == COPTER_GUIDED), None)

        self.wait_until(lambda: all(guided_heartbeat(s) for s in ids), 5,
                        "a heartbeat showing GUIDED from each of %s" % ids)
        for s in ids:
            rec = dict(mode[s])
            hb = guided_heartbeat(s)
            rec["guided_heartbeat"] = None if hb is None else {
                "custom_mode": hb.custom_mode, "base_mode": hb.base_mode,
                "armed": bool(hb.base_mode & mavlink.MAV_MODE_FLAG_SAFETY_ARMED)}
            state = self.master.sysid_state[s]
            rec["pymavlink_flightmode"] = state.flightmode
            rec["pymavlink_armed"] = bool(state.armed)
            vehicles[str(s)]["mode"] = rec

        # pymavlink's count of frames missing from each sender's sequence numbers (post_message)
        report["mav_loss"] = self.master.mav_loss
        report["counts"] = {str(k): v for k, v in self.counts.items()}
        report["addresses"] = {str(k): list(v) for k, v in self.addresses.items()}
        report["elapsed"] = round(self.now(), 6)
        return report


def run_session(args):
    sysids = [int(s) for s in args.sysids.split(",") if s]
    gcs = GroundStation(args.port, args.deadline)
    if args.port_file:
        tmp = args.port_file + ".tmp"
        with open(tmp, "w") as f:
            f.write("%d\n" % gcs.local_port())
        os.replace(tmp, args.port_file)
    try:
        report = gcs.session(sysids, args.interval_us)
    finally:
        gcs.master.close()
    print(json.dumps(report, sort_keys=True))


def run_tlog(args):
    log = mavutil.mavlink_connection(args.file)
    by_sysid, frames, bad, backwards, gaps = {}, 0, 0, 0, 0
    first = last = None
    seqs = {}
    while True:
        m = log.recv_msg()
        if m is None:
            break
        if m.get_type() == "BAD_DATA":
            bad += 1
            continue
        frames += 1
        source = (m.get_srcSystem(), m.get_srcComponent())
        if source in seqs:
            gaps += (m.get_seq() - seqs[source] - 1) % 256
        seqs[source] = m.get_seq()
        t = m._timestamp
        if first is None:
            first = t
        if last is not None and t < last:
            backwards += 1
        last = t
        counts = by_sysid.setdefault(str(m.get_srcSystem()), {})
        counts[m.get_type()] = counts.get(m.get_type(), 0) + 1
    report = {"file": args.file, "frames": frames, "bad_data": bad, "indexed": getattr(log, "_count", None),
              "by_sysid": by_sysid, "first_timestamp": first, "last_timestamp": last, "backwards": backwards,
              "seq_gaps": gaps, "reader": type(log).__name__}
    log.close()
    print(json.dumps(report, sort_keys=True))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="mode", required=True)
    s = sub.add_parser("session")
    s.add_argument("--sysids", required=True, help="comma-separated system ids to expect")
    s.add_argument("--port", type=int, default=0, help="UDP port to listen on, 0 for an ephemeral one")
    s.add_argument("--port-file", help="where to write the port once listening")
    s.add_argument("--deadline", type=float, default=60, help="the whole session ends within this many seconds")
    s.add_argument("--interval-us", type=float, default=200000, help="stream interval to request")
    t = sub.add_parser("tlog")
    t.add_argument("file")
    args = p.parse_args()
    if args.mode == "session":
        run_session(args)
    else:
        run_tlog(args)


if __name__ == "__main__":
    main()
