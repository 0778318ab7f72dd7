#!/usr/bin/env python3
"""Mission, fence and rally uploads to ArduCopter SITL over a lossy link: MAVProxy against ours.

Run by harness/sitl-lossy-uploads.sh (and bench/radio.sh) inside a network namespace of its own (SITL
listens on every interface); see there for the options. One SITL (speedup 1) sends SERIAL0 to a link
model, which passes it on to the ground station under test: --link lossy, harness/lossy_relay.py,
drops each datagram with probability p both ways (one row per loss level, --losses); --link radio,
harness/sik_radio.py, models a pair of SiK radios (--radio-profile sik or worse, one row per profile),
and SITL's SERIAL0 is a 57600 baud port (SERIAL0_BAUD 57 with SIM_BAUDLIMIT_EN 1, without which SITL
reports 1 MB/s for any connected port), as a flight controller's telemetry port wired to a radio.
SERIAL1 (tcp:5762, lossless) is the referee's: before each upload it clears the list (and the link
injects an FTP ResetSessions for each ground station, so a file a lost TerminateSession left open
cannot spill into the next upload), after it it downloads the list and compares it with the file's.

Lists (--kinds): mission (home + 99 waypoints), fence (an inclusion polygon of 12 vertices, a circle
exclusion and a return point), rally (6 points). Tools (--tools, in this order for each list):
  mavproxy-wp    MAVProxy's "wp load FILE", "fence load FILE", "rally load FILE" (done: "Loaded 100
                 waypoints in X.XXs", its own time)
  mavproxy-ftp   MAVProxy's "wp ftpload FILE" (done: "Sent waypoint of length 100 in X.XXs"); missions only
  ours-items     our upload over the mission protocol (bench/ SitlUploads, path ITEMS)
  ours-ftp       our upload over MAVLink FTP (path FTP)
  ours-auto      our default (path AUTO: FTP when the vehicle's AUTOPILOT_VERSION offers it, read back)
  ours-lost-version  ours-auto in a fresh process whose discovery lost the vehicle's first
                 AUTOPILOT_VERSION (the link's "drop-first AUTOPILOT_VERSION" before it starts)
A tool that does not report done within --deadline seconds is stopped and counted as not done.

Writes to --results: samples.jsonl (one line per upload), table.md (remade after every upload),
relay.log (drops and the transfer messages that passed, with marks between uploads), sitl.log,
tool outputs (mavproxy-*.log, ours.log), mission.waypoints.
"""

import argparse
import json
import math
import os
import queue
import re
import select
import socket
import statistics
import subprocess
import sys
import threading
import time

os.environ["MAVLINK20"] = "1"
from pymavlink import mavutil  # noqa: E402

M = mavutil.mavlink
HOME = (40.444233, -7.375234, 820.0)
VEHICLE_PORT, MAVPROXY_PORT, RELAY_PORT, OURS_PORT, FRESH_PORT = 14550, 14551, 14552, 14553, 14554
BRIDGE_TCP_PORT, BRIDGE_UDP_PORT = 14560, 14561
REFEREE = "tcp:127.0.0.1:5762"
GCS_IDS = {"mavproxy": (255, 230), "ours": (208, 190)}   # MAVProxy's defaults; MAVLinkConfig's
TOOLS = ["mavproxy-wp", "mavproxy-ftp", "ours-items", "ours-ftp", "ours-auto", "ours-lost-version"]
LABELS = {"mavproxy-wp": "MAVProxy `wp load`", "mavproxy-ftp": "MAVProxy `wp ftpload`",
          "ours-items": "ours, item protocol", "ours-ftp": "ours, FTP", "ours-auto": "ours, default (AUTO)",
          "ours-lost-version": "ours, default, first AUTOPILOT_VERSION lost"}
OUR_PATHS = {"ours-items": "ITEMS", "ours-ftp": "FTP", "ours-auto": "AUTO", "ours-lost-version": "AUTO"}
KINDS = ["mission", "fence", "rally"]
MISSION_TYPES = {"mission": M.MAV_MISSION_TYPE_MISSION, "fence": M.MAV_MISSION_TYPE_FENCE, "rally": M.MAV_MISSION_TYPE_RALLY}
# MAVProxy's module for each list, and the word its "Loaded N ... in X.XXs" line uses for the items
MAVPROXY_MODULES = {"mission": ("wp", "waypoints"), "fence": ("fence", "fence items"), "rally": ("rally", "rally items")}
# SERIAL0 as a telemetry port wired to a radio: 57600 baud, and SITL held to it (SIM_BAUDLIMIT_EN;
# without it a connected SITL port reports 10 Mbit/s to FTP's burst pacing and never fills); the
# referee's SERIAL1 fast. The limit stops a udpclient port altogether (AP_HAL_SITL's UARTDriver packs
# whole frames of the few bytes a tick allows: none), so SERIAL0 is a tcpclient to a SerialBridge.
RADIO_PARAMS = "SERIAL0_BAUD 57\nSIM_BAUDLIMIT_EN 1\nSERIAL1_BAUD 921\n"


def mission():
    """Home, then 99 NAV_WAYPOINTs on a 10 x 10 grid of about 33 m around it, 20-60 m above home."""
    items = [(0, M.MAV_FRAME_GLOBAL, HOME[0], HOME[1], HOME[2])]
    for i in range(1, 100):
        row, col = (i - 1) // 10, (i - 1) % 10
        lat = round(HOME[0] + (row - 5) * 0.0003, 7)
        lon = round(HOME[1] + (col - 5 if row % 2 == 0 else 4 - col) * 0.0004, 7)
        items.append((i, M.MAV_FRAME_GLOBAL_RELATIVE_ALT, lat, lon, float(20 + (i * 7) % 41)))
    return items


def fence():
    """A return point at home, an inclusion polygon of 12 vertices about 400 m around home (the mission is
    inside), and an exclusion circle of 50 m 250 m east of home: 14 items."""
    items = [(M.MAV_CMD_NAV_FENCE_RETURN_POINT, M.MAV_FRAME_GLOBAL, 0, HOME[0], HOME[1], 0.0)]
    for k in range(12):
        angle = 2 * math.pi * k / 12
        items.append((M.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION, M.MAV_FRAME_GLOBAL, 12,
                      round(HOME[0] + 0.0036 * math.cos(angle), 7), round(HOME[1] + 0.0047 * math.sin(angle), 7), 0.0))
    items.append((M.MAV_CMD_NAV_FENCE_CIRCLE_EXCLUSION, M.MAV_FRAME_GLOBAL, 50, HOME[0], round(HOME[1] + 0.0029, 7), 0.0))
    return [(seq,) + item for seq, item in enumerate(items)]


def rally():
    """6 rally points on a circle of about 200 m around home, 30-55 m above it."""
    return [(k, M.MAV_CMD_NAV_RALLY_POINT, M.MAV_FRAME_GLOBAL_RELATIVE_ALT, 0,
             round(HOME[0] + 0.0018 * math.cos(math.pi * k / 3), 7), round(HOME[1] + 0.0024 * math.sin(math.pi * k / 3), 7),
             float(30 + 5 * k)) for k in range(6)]


def lists():
    """Each kind's items as (seq, command, frame, param1, lat, lon, alt)."""
    return {"mission": [(seq, M.MAV_CMD_NAV_WAYPOINT, frame, 0, lat, lon, alt) for seq, frame, lat, lon, alt in mission()],
            "fence": fence(), "rally": rally()}


def write_waypoints(path, items, home):
    """A QGC WPL 110 file; a mission's first line is its home (CURRENT 1), a fence or rally file has none."""
    with open(path, "w") as f:
        f.write("QGC WPL 110\n")
        for seq, command, frame, p1, lat, lon, alt in items:
            f.write("%d\t%d\t%d\t%d\t%g\t0\t0\t0\t%.7f\t%.7f\t%.2f\t1\n"
                    % (seq, 1 if home and seq == 0 else 0, frame, command, p1, lat, lon, alt))


class Referee:
    """The lossless link (SITL's SERIAL1): clears a list (mission, fence, rally) and downloads it."""

    def __init__(self):
        self.conn = None
        deadline = time.time() + 60
        while self.conn is None:
            try:
                self.conn = mavutil.mavlink_connection(REFEREE, source_system=254, source_component=190, autoreconnect=True)
            except OSError:
                if time.time() > deadline:
                    raise
                time.sleep(0.5)
        if self.conn.wait_heartbeat(timeout=60) is None:
            raise RuntimeError("no heartbeat on " + REFEREE)

    def recv(self, types, timeout):
        end = time.time() + timeout
        while True:
            left = end - time.time()
            if left <= 0:
                return None
            m = self.conn.recv_match(type=types, blocking=True, timeout=left)
            if m is not None and getattr(m, "target_system", 254) == 254:
                return m

    def clear(self, kind, within=20):
        """Clears the list; waits out an upload still in progress (DENIED) for up to `within` s."""
        end = time.time() + within
        while time.time() < end:
            self.conn.mav.mission_clear_all_send(1, 1, MISSION_TYPES[kind])
            ack = self.recv("MISSION_ACK", 1.0)
            if ack is not None and ack.type == M.MAV_MISSION_ACCEPTED:
                return True
            time.sleep(0.5)
        return False

    def download(self, kind, within=20):
        """The vehicle's list as [(seq, command, frame, param1, x, y, z)], or (None, why)."""
        mission_type = MISSION_TYPES[kind]
        end = time.time() + within
        while time.time() < end:
            self.conn.mav.mission_request_list_send(1, 1, mission_type)
            m = self.recv(["MISSION_COUNT", "MISSION_ACK"], 1.0)
            if m is None or m.mission_type != mission_type:
                continue
            if m.get_type() == "MISSION_ACK":   # DENIED: an upload is still in progress
                time.sleep(0.5)
                continue
            items = []
            for seq in range(m.count):
                item = None
                for _ in range(5):
                    self.conn.mav.mission_request_int_send(1, 1, seq, mission_type)
                    item = self.recv("MISSION_ITEM_INT", 1.0)
                    while item is not None and (item.seq != seq or item.mission_type != mission_type):
                        item = self.recv("MISSION_ITEM_INT", 1.0)
                    if item is not None:
                        break
                if item is None:
                    return None, "no item %d on the lossless link" % seq
                items.append((item.seq, item.command, item.frame, item.param1, item.x, item.y, item.z))
            self.conn.mav.mission_ack_send(1, 1, M.MAV_MISSION_ACCEPTED, mission_type)
            return items, None
        return None, "denied for %d s" % within

    def verify(self, kind, expected):
        """None if the vehicle holds the list, else the first difference. A mission's home (item 0) is the
        vehicle's; a fence's items are compared without height (ArduPilot keeps none), a mission's and
        rally points' with it; frames only in a mission (ArduPilot answers fence items in its own)."""
        got, why = self.download(kind)
        if got is None:
            return why
        if len(got) != len(expected):
            return "%d items on the vehicle, not %d" % (len(got), len(expected))
        skip = 1 if kind == "mission" else 0
        for (seq, command, frame, p1, lat, lon, alt), (gseq, cmd, gframe, gp1, x, y, z) in zip(expected[skip:], got[skip:]):
            if (cmd != command or (kind == "mission" and gframe != frame) or abs(gp1 - p1) > 0.01
                    or abs(x - round(lat * 1e7)) > 1 or abs(y - round(lon * 1e7)) > 1
                    or (kind != "fence" and abs(z - alt) > 0.01)):
                return "item %d: %s" % (seq, (cmd, gframe, gp1, x, y, z))
        return None


class SerialBridge:
    """SITL's SERIAL0 as a byte stream (tcpclient, which the baud limit lets through) to the radio model's
    UDP vehicle port: what SITL writes goes on as datagrams from 127.0.0.1:BRIDGE_UDP_PORT, what the
    model sends back there goes to SITL. A daemon thread; the radio model sees bytes, not datagrams."""

    def __init__(self):
        self.server = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        self.server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        self.server.bind(("127.0.0.1", BRIDGE_TCP_PORT))
        self.server.listen(1)
        self.udp = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.udp.bind(("127.0.0.1", BRIDGE_UDP_PORT))
        threading.Thread(target=self.run, daemon=True).start()

    def run(self):
        vehicle, _ = self.server.accept()
        while True:
            ready, _, _ = select.select([vehicle, self.udp], [], [])
            if vehicle in ready:
                data = vehicle.recv(65536)
                if not data:
                    return
                self.udp.sendto(data, ("127.0.0.1", VEHICLE_PORT))
            if self.udp in ready:
                data, addr = self.udp.recvfrom(65536)
                if addr == ("127.0.0.1", VEHICLE_PORT):
                    vehicle.sendall(data)


class Lines:
    """A process's output lines, read by a thread, also written to a log file."""

    def __init__(self, proc, log):
        self.q = queue.Queue()
        self.log = log

        def pump():
            for line in proc.stdout:
                log.write(line)
                log.flush()
                self.q.put(line.rstrip("\n"))
            self.q.put(None)
        threading.Thread(target=pump, daemon=True).start()

    def wait(self, predicate, timeout):
        """The first line the predicate accepts, or None at the timeout or the end of the output."""
        end = time.time() + timeout
        while True:
            left = end - time.time()
            if left <= 0:
                return None
            try:
                line = self.q.get(timeout=left)
            except queue.Empty:
                return None
            if line is None:
                return None
            if predicate(line):
                return line


class Run:

    def __init__(self, a):
        self.a = a
        self.out = a.results
        os.makedirs(self.out, exist_ok=True)
        self.lists = {kind: items for kind, items in lists().items() if kind in a.kinds}
        self.files = {}
        for kind, items in self.lists.items():
            self.files[kind] = os.path.join(self.out, kind + ".waypoints")
            write_waypoints(self.files[kind], items, kind == "mission")
        # the lossy relay's rows are its loss levels; the radio's, its profile (one per run)
        self.conditions = a.losses if a.link == "lossy" else [a.radio_profile]
        self.samples = []
        self.procs = []
        self.started = time.time()
        self.merged = None
        self.round_seconds = []

    def start(self):
        a = self.a
        sitl_dir = os.path.join(self.out, "sitl")
        os.makedirs(sitl_dir, exist_ok=True)
        defaults, serial0 = a.defaults, "udpclient:127.0.0.1:%d" % VEHICLE_PORT
        if a.link == "radio":
            defaults += "," + os.path.join(self.out, "radio.parm")
            with open(os.path.join(self.out, "radio.parm"), "w") as f:
                f.write(RADIO_PARAMS)
            SerialBridge()
            serial0 = "tcpclient:127.0.0.1:%d" % BRIDGE_TCP_PORT
        cmd = [a.sitl, "--model", "+", "-I", "0", "--sysid", "1", "--home", "%f,%f,%.2f,0" % HOME,
               "--speedup", str(a.speedup), "--defaults", defaults, "--serial0", serial0]
        self.sitl = subprocess.Popen(cmd, cwd=sitl_dir, stdout=open(os.path.join(self.out, "sitl.log"), "w"),
                                     stderr=subprocess.STDOUT)
        self.procs.append(self.sitl)
        here = os.path.dirname(__file__)
        link = ([os.path.join(here, "lossy_relay.py")] if a.link == "lossy"
                else [os.path.join(here, "sik_radio.py"), "--profile", a.radio_profile, "--seed", str(a.seed)])
        self.relay = subprocess.Popen([sys.executable] + link + [
            "--vehicle-port", str(VEHICLE_PORT), "--gcs-port", str(MAVPROXY_PORT), "--relay-port", str(RELAY_PORT),
            "--log", os.path.join(self.out, "relay.log"), "--control"], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
        self.procs.append(self.relay)
        print(self.relay.stdout.readline().strip(), flush=True)
        self.referee = Referee()
        print("SITL up; referee connected on " + REFEREE, flush=True)
        self.ours = None
        if any(t in ("ours-items", "ours-ftp", "ours-auto") for t in a.tools):
            self.relay_cmd("gcs %d" % OURS_PORT)
            self.ours, self.ours_lines = self.start_ours(OURS_PORT, "ours.log")
            # discovery's AUTOPILOT_VERSION (whether AUTO may take FTP) must reach it before the link
            # turns to another ground station; ours-lost-version measures an upload without it
            self.ours.stdin.write("capabilities 20\n")
            self.ours.stdin.flush()
            print("our tool: %s" % self.ours_lines.wait(lambda l: l.startswith("capabilities"), 30), flush=True)

    def start_ours(self, port, logname):
        """Our tool on udpin PORT with every list's file, once it has heard the vehicle."""
        log = open(os.path.join(self.out, logname), "a")
        proc = subprocess.Popen(self.a.ours.split() + ["udpin:127.0.0.1:%d" % port] + list(self.files.values()),
                                stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=log, text=True)
        self.procs.append(proc)
        lines = Lines(proc, log)
        if lines.wait(lambda l: l.startswith("ready"), 60) is None:
            raise RuntimeError("our tool did not find the vehicle; see " + logname)
        print("our tool ready on %d" % port, flush=True)
        return proc, lines

    def relay_cmd(self, line):
        self.relay.stdin.write(line + "\n")
        self.relay.stdin.flush()
        answer = self.relay.stdout.readline().strip()
        if not answer.startswith("ok"):
            raise RuntimeError("relay: %s -> %s" % (line, answer))
        return answer

    def reset_ftp_sessions(self):
        for sysid, compid in GCS_IDS.values():
            mav = M.MAVLink(None, srcSystem=sysid, srcComponent=compid)
            msg = M.MAVLink_file_transfer_protocol_message(0, 1, 0, [0, 0, 0, 2] + [0] * 247)
            self.relay_cmd("inject " + bytes(msg.pack(mav)).hex())

    @staticmethod
    def condition_label(cond):
        return "%d %%" % round(cond * 100) if isinstance(cond, float) else cond

    def upload(self, rnd, cond, kind, tool):
        lossy = self.a.link == "lossy"
        what = "round %d %s %s tool %s" % (rnd, "loss %.2f" % cond if lossy else "profile " + cond, kind, tool)
        seed = None
        if lossy:
            seed = rnd * 1000 + int(round(cond * 100)) * 10 + TOOLS.index(tool) + 100000 * KINDS.index(kind)
            self.relay_cmd("loss 0")
        self.relay_cmd("mark %s: preparing" % what)
        self.reset_ftp_sessions()
        time.sleep(0.2)
        if not self.referee.clear(kind):
            raise RuntimeError("could not clear the " + kind)
        self.relay_cmd("gcs %d" % (MAVPROXY_PORT if tool.startswith("mavproxy") else
                                   FRESH_PORT if tool == "ours-lost-version" else OURS_PORT))
        self.relay_cmd("stats")
        if lossy:
            self.relay_cmd("seed %d" % seed)
            self.relay_cmd("loss %s" % cond)
        self.relay_cmd("mark %s seed %s: upload" % (what, seed))
        t0 = time.time()
        if tool.startswith("mavproxy"):
            sample = self.mavproxy(tool, kind, rnd, cond)
        elif tool == "ours-lost-version":
            sample = self.ours_fresh(kind)
        else:
            sample = self.ours_upload(self.ours, self.ours_lines, OUR_PATHS[tool], kind)
        wall = time.time() - t0
        stats = self.relay_cmd("stats")
        if lossy:
            self.relay_cmd("loss 0")
        self.relay_cmd("mark %s: verifying" % what)
        why = self.referee.verify(kind, self.lists[kind])
        sample.update({"round": rnd, "loss": cond if lossy else None, "kind": kind, "tool": tool, "tag": self.a.tag,
                       "link": self.a.link, "profile": None if lossy else cond, "seed": seed if lossy else self.a.seed,
                       "wall_s": round(wall, 3), "verified": why is None, "difference": why, "link_stats": stats[3:],
                       "at": time.strftime("%H:%M:%S"), "load1": round(os.getloadavg()[0], 2)})
        counts = re.search(r"up (\d+) (\d+) down (\d+) (\d+)", stats)   # the relay's datagrams, the radio's air packets
        if counts:
            unit = "datagrams" if lossy else "air_packets"
            sample.update(zip([unit + "_up", "dropped_up", unit + "_down", "dropped_down"], map(int, counts.groups())))
        self.relay_cmd("mark %s: done=%s verified=%s" % (what, sample["done"], why is None))
        with open(os.path.join(self.out, "samples.jsonl"), "a") as f:
            f.write(json.dumps(sample) + "\n")
        self.samples.append(sample)
        print("round %d %-5s %-7s %-17s done=%-5s verified=%-5s time=%s %s" % (
            rnd, self.condition_label(cond), kind, tool, sample["done"], why is None, sample.get("time_s"),
            sample.get("error") or why or ""), flush=True)
        self.table()

    def mavproxy(self, tool, kind, rnd, cond):
        """One MAVProxy process per upload: connect, wait for the vehicle, then the command, as a user types it."""
        a = self.a
        module, word = MAVPROXY_MODULES[kind]
        log = open(os.path.join(self.out, "mavproxy-%s-%s-r%d-%s.log" % (
            tool[9:], kind, rnd, self.condition_label(cond).replace(" %", ""))), "w")
        # only the list's module (and FTP's, which does nothing until told): each module fetches its list
        # from the vehicle when it connects
        proc = subprocess.Popen([a.mavproxy, "--master", "udp:127.0.0.1:%d" % MAVPROXY_PORT, "--default-modules",
                                 "wp,ftp" if kind == "mission" else module, "--streamrate", "-1", "--no-state"],
                                cwd=self.out, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        lines = Lines(proc, log)
        sample = {"done": False, "time_s": None, "error": None}
        n = len(self.lists[kind])
        try:
            if lines.wait(lambda l: "Detected vehicle" in l, 60) is None:
                sample["error"] = "MAVProxy never heard the vehicle"
                return sample
            command = "%s %s %s" % (module, "load" if tool == "mavproxy-wp" else "ftpload", self.files[kind])
            proc.stdin.write(command + "\n")
            proc.stdin.flush()
            t0 = time.time()
            # mission_item_protocol.py: "Loaded %u %s in %.2fs" (the last item sent), "Sent %s of length %u in %.2fs"
            # (every write ACKed; its TerminateSession follows), "Failed to send %s", "Unable to load"; mavproxy_ftp.py:
            # "Create failed", "Write failed" (a NAK)
            done = re.compile(r"Loaded %d %s in ([0-9.]+)s" % (n, word) if tool == "mavproxy-wp"
                              else r"Sent waypoint of length %d in ([0-9.]+)s" % n)
            failed = ("Failed to send", "Create failed", "Write failed", "Unable to load")
            line = lines.wait(lambda l: done.search(l) or any(f in l for f in failed), a.deadline)
            sample["command_to_done_s"] = round(time.time() - t0, 3)
            if line is None:
                sample["error"] = "not done in %d s" % a.deadline
            elif done.search(line):
                sample["done"] = True
                sample["time_s"] = float(done.search(line).group(1))
                time.sleep(0.5)   # its TerminateSession (ftpload) goes out right after the line
            else:
                sample["error"] = line.strip()
            return sample
        finally:
            proc.terminate()   # its quit handler
            try:
                proc.wait(5)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()
            log.close()

    def ours_upload(self, proc, lines, path, kind):
        proc.stdin.write("upload %s %d %s\n" % (path, self.a.deadline, kind))
        proc.stdin.flush()
        line = lines.wait(lambda l: l.startswith("result "), self.a.deadline + 60)
        if line is None:
            return {"done": False, "time_s": None, "error": "our tool gave no result"}
        r = json.loads(line[len("result "):])
        return {"done": r["done"], "time_s": r["time_s"] if r["done"] else None, "error": r.get("error"),
                "resends": r.get("resends"), "note": r.get("note"), "self_verified": r.get("verified"),
                "attempt_s": r["time_s"], "ftp_offered": r.get("ftp_offered")}

    def ours_fresh(self, kind):
        """Our default upload from a process just started, whose discovery's AUTOPILOT_VERSION the link dropped."""
        self.relay_cmd("drop-first AUTOPILOT_VERSION")
        proc, lines = self.start_ours(FRESH_PORT, "ours-fresh.log")
        try:
            return self.ours_upload(proc, lines, "AUTO", kind)
        finally:
            self.quit(proc)

    @staticmethod
    def quit(proc):
        if proc.poll() is None:
            try:
                proc.stdin.write("quit\n")
                proc.stdin.flush()
            except OSError:
                pass
        try:
            proc.wait(5)
        except subprocess.TimeoutExpired:
            proc.terminate()
            try:
                proc.wait(5)
            except subprocess.TimeoutExpired:
                proc.kill()

    @staticmethod
    def verified_times(samples):
        return sorted(s["time_s"] for s in samples if s["verified"] and s["time_s"] is not None)

    def describe_links(self):
        links = []
        for s in self.samples:
            text = ("each datagram dropped with probability p both ways (harness/lossy_relay.py, seeded)"
                    if s.get("link", "lossy") == "lossy" else
                    "a SiK radio pair (harness/sik_radio.py), profile %s, seed %s; SERIAL0 at 57600 baud (SERIAL0_BAUD 57, "
                    "SIM_BAUDLIMIT_EN 1)" % (s["profile"], s["seed"]))
            if text not in links:
                links.append(text)
        return "; ".join(links)

    def table(self):
        a = self.a
        rounds = max(s["round"] for s in self.samples)
        kinds = [k for k in KINDS if any(s.get("kind", "mission") == k for s in self.samples)]
        n = {kind: len(items) for kind, items in lists().items()}
        lines = ["# Uploads to ArduCopter SITL over a lossy link", "",
                 "ArduPilot %s (ArduCopter SITL, %s), --speedup %s, home %.6f,%.6f,%.0f; %s; %s; every upload checked "
                 "by a download on a second, lossless SITL port; deadline %d s; %d round(s) so far, tools interleaved "
                 "within each round; %s." % (
                     a.commit, os.path.basename(a.defaults), a.speedup, HOME[0], HOME[1], HOME[2],
                     ", ".join({"mission": "a %d-item mission (home + %d NAV_WAYPOINTs)" % (n["mission"], n["mission"] - 1),
                                "fence": "a %d-item fence (return point, 12-vertex inclusion polygon, exclusion circle)"
                                         % n["fence"],
                                "rally": "%d rally points" % n["rally"]}[k] for k in kinds),
                     self.describe_links(), a.deadline, rounds,
                     ("started %s UTC, %.0f min so far" % (time.strftime("%Y-%m-%d %H:%M", time.gmtime(self.started)),
                                                            (time.time() - self.started) / 60)) if self.merged is None
                     else "merged from the runs in " + ", ".join(self.merged)),
                 "", "Cells: verified on the vehicle / reported done / uploads, median (min-max) time of the verified "
                 "ones (MAVProxy: the time it prints; ours: from the call to the result).", ""]
        if self.round_seconds:
            lines[2] += " Rounds took " + ", ".join("%.0f" % r for r in self.round_seconds) + " s."
        columns = sorted({(s["tool"], s.get("tag", "")) for s in self.samples if s["tool"] in a.tools},
                         key=lambda c: (TOOLS.index(c[0]), c[1]))
        conditions = []
        for s in self.samples:
            c = self.condition_label(s["loss"] if s.get("link", "lossy") == "lossy" else s["profile"])
            if c not in conditions:
                conditions.append(c)
        rows = [(c, k) for c in conditions for k in kinds]

        def of(row, tool, tag=None):
            """The row's samples of the tool, of every run's tag with None."""
            return [s for s in self.samples if s["tool"] == tool and tag in (None, s.get("tag", ""))
                    and self.condition_label(s["loss"] if s.get("link", "lossy") == "lossy" else s["profile"]) == row[0]
                    and s.get("kind", "mission") == row[1]]

        def median(samples):
            times = self.verified_times(samples)
            return statistics.median(times) if times else None

        lines.append("| link | list | " + " | ".join(LABELS[t] + (" (%s)" % tag if tag else "") for t, tag in columns) + " |")
        lines.append("|---|---|" + "---|" * len(columns))
        for row in rows:
            cells = []
            for t, tag in columns:
                ss = of(row, t, tag)
                times = self.verified_times(ss)
                if not ss:
                    cells.append("-")
                    continue
                cells.append("%d/%d/%d, %s" % (sum(1 for s in ss if s["verified"]), sum(1 for s in ss if s["done"]), len(ss),
                                               "%.2f s (%.2f-%.2f)" % (statistics.median(times), times[0], times[-1])
                                               if times else "-"))
            lines.append("| %s | %s | " % row + " | ".join(cells) + " |")
        ratios = []
        for t, tag in [c for c in columns if c[0].startswith("ours")]:
            cells = []
            for row in rows:
                ours, theirs = median(of(row, t, tag)), median(of(row, "mavproxy-wp"))
                cells.append("x%.3f" % (ours / theirs) if ours and theirs else "-")
            ratios.append("| %s%s | " % (LABELS[t], (" (%s)" % tag) if tag else "") + " | ".join(cells) + " |")
        if ratios:
            lines += ["", "| median time of the verified uploads / MAVProxy `load`'s | "
                      + " | ".join("%s, %s" % row for row in rows) + " |", "|---|" + "---|" * len(rows)] + ratios
        lines += ["", "Not done or not verified:", ""]
        for s in self.samples:
            if not s["done"] or not s["verified"]:
                lines.append("- round %d, %s, %s, %s%s: done=%s verified=%s; %s%s" % (
                    s["round"], self.condition_label(s["loss"] if s.get("link", "lossy") == "lossy" else s["profile"]),
                    s.get("kind", "mission"), s["tool"], (" (%s)" % s["tag"]) if s.get("tag") else "", s["done"],
                    s["verified"], s.get("error") or "", ("; vehicle: " + s["difference"]) if s.get("difference") else ""))
        with open(os.path.join(self.out, "table.md"), "w") as f:
            f.write("\n".join(lines) + "\n")

    def run(self):
        a = self.a
        self.start()
        for rnd in range(1, a.rounds + 1):
            t0 = time.time()
            for cond in self.conditions:
                for kind in a.kinds:
                    for tool in [t for t in TOOLS if t in a.tools]:
                        if tool == "mavproxy-ftp" and kind != "mission":
                            continue
                        if (tool.startswith("mavproxy") and a.link == "lossy" and cond >= 0.2
                                and rnd > a.mavproxy_rounds_high):
                            continue
                        if a.stop_at and time.time() > a.stop_at:
                            print("stopping: --stop-at reached", flush=True)
                            return
                        self.upload(rnd, cond, kind, tool)
            self.round_seconds.append(time.time() - t0)
            print("round %d took %.0f s" % (rnd, self.round_seconds[-1]), flush=True)
            self.table()

    def close(self):
        if self.ours is not None:
            self.quit(self.ours)
        self.quit(self.relay)
        for p in reversed(self.procs):
            try:
                p.wait(5)
            except subprocess.TimeoutExpired:
                p.terminate()
                try:
                    p.wait(5)
                except subprocess.TimeoutExpired:
                    p.kill()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sitl", help="the arducopter binary (not with --merge)")
    ap.add_argument("--defaults", default="copter.parm", help="its parameter file (copter.parm)")
    ap.add_argument("--commit", default="?", help="the ArduPilot commit, for the table")
    ap.add_argument("--results", required=True)
    ap.add_argument("--mavproxy", default="mavproxy.py")
    ap.add_argument("--ours", default="", help="the command line of bench's SitlUploads, without its arguments")
    ap.add_argument("--link", choices=["lossy", "radio"], default="lossy",
                    help="lossy: harness/lossy_relay.py at --losses; radio: harness/sik_radio.py, --radio-profile")
    ap.add_argument("--radio-profile", choices=["sik", "worse"], default="sik")
    ap.add_argument("--seed", type=int, default=1, help="the radio model's seed (--link radio)")
    ap.add_argument("--kinds", default="mission", help="the lists uploaded, of " + ",".join(KINDS))
    ap.add_argument("--tools", default="mavproxy-wp,mavproxy-ftp,ours-items,ours-ftp")
    ap.add_argument("--losses", default="0,0.05,0.1,0.2,0.3")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--mavproxy-rounds-high", type=int, default=99, help="MAVProxy at 20 %% loss and more only in the first N rounds")
    ap.add_argument("--deadline", type=int, default=120)
    ap.add_argument("--speedup", default="1")
    ap.add_argument("--stop-at", type=float, default=0, help="start no upload after this Unix time")
    ap.add_argument("--tag", default="", help="a word for this run's columns (e.g. the code's commit)")
    ap.add_argument("--merge", nargs="+", metavar="DIR",
                    help="run nothing: write --results/table.md from these results directories' samples")
    a = ap.parse_args()
    a.tools = [t for t in a.tools.split(",") if t]
    for t in a.tools:
        if t not in TOOLS:
            ap.error("unknown tool " + t)
    a.kinds = [k for k in a.kinds.split(",") if k]
    for k in a.kinds:
        if k not in KINDS:
            ap.error("unknown list " + k)
    a.losses = [float(x) for x in a.losses.split(",")]
    if not a.merge and not a.sitl:
        ap.error("--sitl is needed to run")
    r = Run(a)
    if a.merge:
        for arg in a.merge:
            d, _, tag = arg.partition("=")
            with open(os.path.join(d, "samples.jsonl")) as f:
                for line in filter(str.strip, f):
                    sample = json.loads(line)
                    sample["tag"] = tag or sample.get("tag", "")
                    r.samples.append(sample)
        r.merged = [arg.partition("=")[0] for arg in a.merge]
        r.table()
        print("table in " + os.path.join(a.results, "table.md"), flush=True)
        return
    try:
        r.run()
    finally:
        r.close()
    print("results in " + a.results, flush=True)


if __name__ == "__main__":
    main()
