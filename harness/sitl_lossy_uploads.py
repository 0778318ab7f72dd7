#!/usr/bin/env python3
"""Mission uploads to ArduCopter SITL through a seeded lossy relay: MAVProxy against ours.

Run by harness/sitl-lossy-uploads.sh inside a network namespace of its own (SITL listens on every
interface); see there for the options. One SITL (speedup 1) sends SERIAL0 to harness/lossy_relay.py,
which passes it on to the ground station under test, dropping each datagram with probability p both
ways; SERIAL1 (tcp:5762, lossless) is the referee's: before each upload it clears the mission (and
the relay injects an FTP ResetSessions for each ground station, so a file a lost TerminateSession
left open cannot spill into the next upload), after it it downloads the mission and compares it
with the file's.

Tools (--tools, in this order within each loss level of a round):
  mavproxy-wp    MAVProxy's "wp load FILE" (done: "Loaded 100 waypoints in X.XXs", its own time)
  mavproxy-ftp   MAVProxy's "wp ftpload FILE" (done: "Sent mission of length 100 in X.XXs")
  ours-items     our upload over the mission protocol (bench/ SitlUploads, path ITEMS)
  ours-ftp       our upload over MAVLink FTP (path FTP)
A tool that does not report done within --deadline seconds is stopped and counted as not done.

Writes to --results: samples.jsonl (one line per upload), table.md (remade after every upload),
relay.log (drops and the transfer messages that passed, with marks between uploads), sitl.log,
tool outputs (mavproxy-*.log, ours.log), mission.waypoints.
"""

import argparse
import json
import os
import queue
import re
import statistics
import subprocess
import sys
import threading
import time

os.environ["MAVLINK20"] = "1"
from pymavlink import mavutil  # noqa: E402

M = mavutil.mavlink
HOME = (40.444233, -7.375234, 820.0)
VEHICLE_PORT, MAVPROXY_PORT, RELAY_PORT, OURS_PORT = 14550, 14551, 14552, 14553
REFEREE = "tcp:127.0.0.1:5762"
GCS_IDS = {"mavproxy": (255, 230), "ours": (208, 190)}   # MAVProxy's defaults; MAVLinkConfig's
TOOLS = ["mavproxy-wp", "mavproxy-ftp", "ours-items", "ours-ftp"]
LABELS = {"mavproxy-wp": "MAVProxy `wp load`", "mavproxy-ftp": "MAVProxy `wp ftpload`",
          "ours-items": "ours, item protocol", "ours-ftp": "ours, FTP"}


def mission():
    """Home, then 99 NAV_WAYPOINTs on a 10 x 10 grid of about 33 m around it, 20-60 m above home."""
    items = [(0, M.MAV_FRAME_GLOBAL, HOME[0], HOME[1], HOME[2])]
    for i in range(1, 100):
        row, col = (i - 1) // 10, (i - 1) % 10
        lat = round(HOME[0] + (row - 5) * 0.0003, 7)
        lon = round(HOME[1] + (col - 5 if row % 2 == 0 else 4 - col) * 0.0004, 7)
        items.append((i, M.MAV_FRAME_GLOBAL_RELATIVE_ALT, lat, lon, float(20 + (i * 7) % 41)))
    return items


def write_waypoints(path, items):
    with open(path, "w") as f:
        f.write("QGC WPL 110\n")
        for seq, frame, lat, lon, alt in items:
            f.write("%d\t%d\t%d\t%d\t0\t0\t0\t0\t%.7f\t%.7f\t%.2f\t1\n"
                    % (seq, 1 if seq == 0 else 0, frame, M.MAV_CMD_NAV_WAYPOINT, lat, lon, alt))


class Referee:
    """The lossless link (SITL's SERIAL1): clears the mission and downloads it."""

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

    def clear(self, within=20):
        """Clears the mission; waits out an upload still in progress (DENIED) for up to `within` s."""
        end = time.time() + within
        while time.time() < end:
            self.conn.mav.mission_clear_all_send(1, 1, M.MAV_MISSION_TYPE_MISSION)
            ack = self.recv("MISSION_ACK", 1.0)
            if ack is not None and ack.type == M.MAV_MISSION_ACCEPTED:
                return True
            time.sleep(0.5)
        return False

    def download(self, within=20):
        """The vehicle's mission as [(seq, command, frame, x, y, z)], or (None, why)."""
        end = time.time() + within
        while time.time() < end:
            self.conn.mav.mission_request_list_send(1, 1, M.MAV_MISSION_TYPE_MISSION)
            m = self.recv(["MISSION_COUNT", "MISSION_ACK"], 1.0)
            if m is None:
                continue
            if m.get_type() == "MISSION_ACK":   # DENIED: an upload is still in progress
                time.sleep(0.5)
                continue
            items = []
            for seq in range(m.count):
                item = None
                for _ in range(5):
                    self.conn.mav.mission_request_int_send(1, 1, seq, M.MAV_MISSION_TYPE_MISSION)
                    item = self.recv("MISSION_ITEM_INT", 1.0)
                    while item is not None and item.seq != seq:
                        item = self.recv("MISSION_ITEM_INT", 1.0)
                    if item is not None:
                        break
                if item is None:
                    return None, "no item %d on the lossless link" % seq
                items.append((item.seq, item.command, item.frame, item.x, item.y, item.z))
            self.conn.mav.mission_ack_send(1, 1, M.MAV_MISSION_ACCEPTED, M.MAV_MISSION_TYPE_MISSION)
            return items, None
        return None, "denied for %d s" % within

    def verify(self, expected):
        """None if the vehicle holds the mission (home, item 0, is the vehicle's), else the first difference."""
        got, why = self.download()
        if got is None:
            return why
        if len(got) != len(expected):
            return "%d items on the vehicle, not %d" % (len(got), len(expected))
        for (seq, frame, lat, lon, alt), (gseq, cmd, gframe, x, y, z) in zip(expected[1:], got[1:]):
            if (cmd != M.MAV_CMD_NAV_WAYPOINT or gframe != frame or abs(x - round(lat * 1e7)) > 1
                    or abs(y - round(lon * 1e7)) > 1 or abs(z - alt) > 0.01):
                return "item %d: %s" % (seq, (cmd, gframe, x, y, z))
        return None


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
        self.items = mission()
        self.wpfile = os.path.join(self.out, "mission.waypoints")
        write_waypoints(self.wpfile, self.items)
        self.samples = []
        self.procs = []
        self.started = time.time()
        self.merged = None
        self.round_seconds = []

    def start(self):
        a = self.a
        sitl_dir = os.path.join(self.out, "sitl")
        os.makedirs(sitl_dir, exist_ok=True)
        cmd = [a.sitl, "--model", "+", "-I", "0", "--sysid", "1", "--home", "%f,%f,%.2f,0" % HOME,
               "--speedup", str(a.speedup), "--defaults", a.defaults, "--serial0", "udpclient:127.0.0.1:%d" % VEHICLE_PORT]
        self.sitl = subprocess.Popen(cmd, cwd=sitl_dir, stdout=open(os.path.join(self.out, "sitl.log"), "w"),
                                     stderr=subprocess.STDOUT)
        self.procs.append(self.sitl)
        self.relay = subprocess.Popen([sys.executable, os.path.join(os.path.dirname(__file__), "lossy_relay.py"),
                                       "--vehicle-port", str(VEHICLE_PORT), "--gcs-port", str(MAVPROXY_PORT),
                                       "--relay-port", str(RELAY_PORT), "--log", os.path.join(self.out, "relay.log"),
                                       "--control"], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
        self.procs.append(self.relay)
        print(self.relay.stdout.readline().strip(), flush=True)
        self.referee = Referee()
        print("SITL up; referee connected on " + REFEREE, flush=True)
        self.ours = None
        if any(t.startswith("ours") for t in a.tools):
            log = open(os.path.join(self.out, "ours.log"), "a")
            self.relay_cmd("gcs %d" % OURS_PORT)
            self.ours = subprocess.Popen(a.ours.split() + ["udpin:127.0.0.1:%d" % OURS_PORT, self.wpfile],
                                         stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=log, text=True)
            self.procs.append(self.ours)
            self.ours_lines = Lines(self.ours, log)
            if self.ours_lines.wait(lambda l: l.startswith("ready"), 60) is None:
                raise RuntimeError("our tool did not find the vehicle; see ours.log")
            print("our tool ready", flush=True)

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

    def upload(self, rnd, loss, tool):
        seed = rnd * 1000 + int(round(loss * 100)) * 10 + TOOLS.index(tool)
        self.relay_cmd("loss 0")
        self.relay_cmd("mark round %d loss %.2f tool %s seed %d: preparing" % (rnd, loss, tool, seed))
        self.reset_ftp_sessions()
        time.sleep(0.2)
        if not self.referee.clear():
            raise RuntimeError("could not clear the mission")
        self.relay_cmd("gcs %d" % (OURS_PORT if tool.startswith("ours") else MAVPROXY_PORT))
        self.relay_cmd("stats")
        self.relay_cmd("seed %d" % seed)
        self.relay_cmd("loss %s" % loss)
        self.relay_cmd("mark round %d loss %.2f tool %s seed %d: upload" % (rnd, loss, tool, seed))
        t0 = time.time()
        if tool.startswith("mavproxy"):
            sample = self.mavproxy(tool, rnd, loss)
        else:
            sample = self.ours_upload(tool)
        wall = time.time() - t0
        stats = self.relay_cmd("stats").split()
        self.relay_cmd("loss 0")
        self.relay_cmd("mark round %d loss %.2f tool %s: verifying" % (rnd, loss, tool))
        why = self.referee.verify(self.items)
        sample.update({"round": rnd, "loss": loss, "tool": tool, "tag": self.a.tag, "seed": seed, "wall_s": round(wall, 3),
                       "verified": why is None, "difference": why,
                       "datagrams_up": int(stats[2]), "dropped_up": int(stats[3]),
                       "datagrams_down": int(stats[5]), "dropped_down": int(stats[6]), "at": time.strftime("%H:%M:%S"),
                       "load1": round(os.getloadavg()[0], 2)})
        self.relay_cmd("mark round %d loss %.2f tool %s: done=%s verified=%s" % (rnd, loss, tool, sample["done"], why is None))
        with open(os.path.join(self.out, "samples.jsonl"), "a") as f:
            f.write(json.dumps(sample) + "\n")
        self.samples.append(sample)
        print("round %d loss %2d%% %-12s done=%-5s verified=%-5s time=%s %s" % (
            rnd, loss * 100, tool, sample["done"], why is None, sample.get("time_s"), sample.get("error") or why or ""), flush=True)
        self.table()

    def mavproxy(self, tool, rnd, loss):
        """One MAVProxy process per upload: connect, wait for the vehicle, then the command, as a user types it."""
        a = self.a
        log = open(os.path.join(self.out, "mavproxy-%s-r%d-%02d.log" % (tool[9:], rnd, round(loss * 100))), "w")
        proc = subprocess.Popen([a.mavproxy, "--master", "udp:127.0.0.1:%d" % MAVPROXY_PORT, "--default-modules", "wp,ftp",
                                 "--streamrate", "-1", "--no-state"], cwd=self.out, stdin=subprocess.PIPE,
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        lines = Lines(proc, log)
        sample = {"done": False, "time_s": None, "error": None}
        try:
            if lines.wait(lambda l: "Detected vehicle" in l, 60) is None:
                sample["error"] = "MAVProxy never heard the vehicle"
                return sample
            command = ("wp load " if tool == "mavproxy-wp" else "wp ftpload ") + self.wpfile
            proc.stdin.write(command + "\n")
            proc.stdin.flush()
            t0 = time.time()
            # mission_item_protocol.py: "Loaded %u %s in %.2fs" (the last item sent), "Sent %s of length %u in %.2fs"
            # (every write ACKed; its TerminateSession follows), "Failed to send %s"; mavproxy_ftp.py: "Create failed",
            # "Write failed" (a NAK)
            done = re.compile(r"Loaded 100 waypoints in ([0-9.]+)s" if tool == "mavproxy-wp"
                              else r"Sent waypoint of length 100 in ([0-9.]+)s")
            line = lines.wait(lambda l: done.search(l) or "Failed to send" in l or "Create failed" in l or "Write failed" in l,
                              a.deadline)
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

    def ours_upload(self, tool):
        path = "ITEMS" if tool == "ours-items" else "FTP"
        self.ours.stdin.write("upload %s %d\n" % (path, self.a.deadline))
        self.ours.stdin.flush()
        line = self.ours_lines.wait(lambda l: l.startswith("result "), self.a.deadline + 60)
        if line is None:
            return {"done": False, "time_s": None, "error": "our tool gave no result"}
        r = json.loads(line[len("result "):])
        return {"done": r["done"], "time_s": r["time_s"] if r["done"] else None, "error": r.get("error"),
                "resends": r.get("resends"), "note": r.get("note"), "self_verified": r.get("verified"),
                "attempt_s": r["time_s"]}

    @staticmethod
    def median(samples):
        """The median time of the verified uploads among samples, None without any."""
        times = [s["time_s"] for s in samples if s["verified"] and s["time_s"] is not None]
        return statistics.median(times) if times else None

    def table(self):
        a = self.a
        rounds = max(s["round"] for s in self.samples)
        lines = ["# Mission uploads to ArduCopter SITL through a lossy relay", "",
                 "ArduPilot %s (ArduCopter SITL, %s), --speedup %s, home %.6f,%.6f,%.0f; a 100-item mission (home + 99 "
                 "NAV_WAYPOINTs); each datagram dropped with probability p both ways (harness/lossy_relay.py, seeded); "
                 "every upload checked by a download on a second, lossless SITL port; deadline %d s; %d round(s) so far, "
                 "tools interleaved within each round; %s." % (
                     a.commit, os.path.basename(a.defaults), a.speedup, HOME[0], HOME[1], HOME[2], a.deadline, rounds,
                     ("started %s UTC, %.0f min so far" % (time.strftime("%Y-%m-%d %H:%M", time.gmtime(self.started)),
                                                            (time.time() - self.started) / 60)) if self.merged is None
                     else "merged from the runs in " + ", ".join(self.merged)),
                 "", "Cells: verified on the vehicle / reported done / uploads, median time of the verified ones "
                 "(MAVProxy: the time it prints; ours: from the call to the result).", ""]
        if self.round_seconds:
            lines[2] += " Rounds took " + ", ".join("%.0f" % r for r in self.round_seconds) + " s."
        columns = sorted({(s["tool"], s.get("tag", "")) for s in self.samples if s["tool"] in a.tools},
                         key=lambda c: (TOOLS.index(c[0]), c[1]))
        lines.append("| loss | " + " | ".join(LABELS[t] + (" (%s)" % tag if tag else "") for t, tag in columns) + " |")
        lines.append("|---|" + "---|" * len(columns))
        for loss in a.losses:
            cells = []
            for t, tag in columns:
                ss = [s for s in self.samples if s["tool"] == t and s.get("tag", "") == tag and s["loss"] == loss]
                if not ss:
                    cells.append("-")
                    continue
                med = self.median(ss)
                cells.append("%d/%d/%d, %s" % (sum(1 for s in ss if s["verified"]), sum(1 for s in ss if s["done"]), len(ss),
                                               "%.2f s" % med if med else "-"))
            lines.append("| %d %% | " % round(loss * 100) + " | ".join(cells) + " |")
        theirs = {loss: self.median([s for s in self.samples if s["tool"] == "mavproxy-wp" and s["loss"] == loss])
                  for loss in a.losses}
        ratios = []
        for t, tag in [c for c in columns if c[0].startswith("ours")]:
            cells = []
            for loss in a.losses:
                ours = self.median([s for s in self.samples if s["tool"] == t and s.get("tag", "") == tag and s["loss"] == loss])
                cells.append("x%.3f" % (ours / theirs[loss]) if ours and theirs[loss] else "-")
            ratios.append("| %s%s | " % (LABELS[t], (" (%s)" % tag) if tag else "") + " | ".join(cells) + " |")
        if ratios:
            lines += ["", "| median time of the verified uploads / MAVProxy `wp load`'s | "
                      + " | ".join("%d %%" % round(loss * 100) for loss in a.losses) + " |",
                      "|---|" + "---|" * len(a.losses)] + ratios
        lines += ["", "Not done or not verified:", ""]
        for s in self.samples:
            if not s["done"] or not s["verified"]:
                lines.append("- round %d, %d %%, %s%s: done=%s verified=%s; %s%s" % (
                    s["round"], round(s["loss"] * 100), s["tool"], (" (%s)" % s["tag"]) if s.get("tag") else "", s["done"], s["verified"], s.get("error") or "",
                    ("; vehicle: " + s["difference"]) if s.get("difference") else ""))
        with open(os.path.join(self.out, "table.md"), "w") as f:
            f.write("\n".join(lines) + "\n")

    def run(self):
        a = self.a
        self.start()
        for rnd in range(1, a.rounds + 1):
            t0 = time.time()
            for loss in a.losses:
                for tool in [t for t in TOOLS if t in a.tools]:
                    if tool.startswith("mavproxy") and loss >= 0.2 and rnd > a.mavproxy_rounds_high:
                        continue
                    if a.stop_at and time.time() > a.stop_at:
                        print("stopping: --stop-at reached", flush=True)
                        return
                    self.upload(rnd, loss, tool)
            self.round_seconds.append(time.time() - t0)
            print("round %d took %.0f s" % (rnd, self.round_seconds[-1]), flush=True)
            self.table()

    def close(self):
        if self.ours is not None and self.ours.poll() is None:
            try:
                self.ours.stdin.write("quit\n")
                self.ours.stdin.flush()
            except OSError:
                pass
        if self.relay.poll() is None:
            try:
                self.relay.stdin.write("quit\n")
                self.relay.stdin.flush()
            except OSError:
                pass
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
    ap.add_argument("--sitl", required=True, help="the arducopter binary")
    ap.add_argument("--defaults", required=True, help="its parameter file (copter.parm)")
    ap.add_argument("--commit", default="?", help="the ArduPilot commit, for the table")
    ap.add_argument("--results", required=True)
    ap.add_argument("--mavproxy", default="mavproxy.py")
    ap.add_argument("--ours", default="", help="the command line of bench's SitlUploads, without its arguments")
    ap.add_argument("--tools", default=",".join(TOOLS))
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
    a.losses = [float(x) for x in a.losses.split(",")]
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
