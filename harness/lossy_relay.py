#!/usr/bin/env python3
"""A seeded lossy UDP relay between one MAVLink vehicle and one ground station, on 127.0.0.1 only.

  lossy_relay.py --vehicle-port V --gcs-port G [--relay-port R] [--loss P | --loss-up P --loss-down P]
                 [--seed S] [--log FILE] [--control]

The vehicle (ArduPilot SITL with --serial0 udpclient:127.0.0.1:V) sends to V; the relay sends what it
hears there to the ground station listening on 127.0.0.1:G (MAVProxy's --master udp:127.0.0.1:G, our
udpin:127.0.0.1:G), from its own socket 127.0.0.1:R, and sends what the ground station sends back to
R on to the vehicle's address. Each datagram is dropped with probability loss-up (ground station to
vehicle) or loss-down (vehicle to ground station), from a random.Random per direction seeded from
--seed, so a run can be repeated up to the timing of its datagrams. Datagrams to R from any other
address than the current ground station's are ignored (counted), so a second program listening
elsewhere cannot reach the vehicle through the relay.

Every socket is bound to 127.0.0.1 and every datagram goes to 127.0.0.1: the relay never listens on
or sends to another interface.

The log (--log) has one line per dropped datagram, and one per datagram carrying a mission-protocol,
MAVLink FTP or STATUSTEXT message that passed, so a transfer can be followed from it:

  12.345 drop down MISSION_REQUEST_INT seq=17 | ATTITUDE
  12.351 pass up MISSION_ITEM_INT seq=17

(seconds since the relay started; "up" is ground station to vehicle, "down" vehicle to ground
station; the MAVLink messages a datagram held, the interesting ones decoded).

With --control the relay reads commands on stdin, one a line, and answers each on stdout
("ok ..." or "error ..."), so a driver can change the conditions between transfers:

  loss P | loss UP DOWN   set the loss probabilities
  seed S                  re-seed both directions (up from 2 S, down from 2 S + 1)
  gcs PORT                send the vehicle's datagrams to 127.0.0.1:PORT from now on
  mark TEXT               write "mark TEXT" in the log
  inject HEX              send these bytes (a MAVLink frame) to the vehicle, never dropped
  outage S                drop every datagram both ways for S seconds from now (a link lost mid-flight),
                          then the loss probabilities again; logged as "mark outage ..." lines
  drop-first NAME         drop the next datagram to the ground station that carries the message NAME
                          (e.g. AUTOPILOT_VERSION: a reply to discovery lost), then forward as before
  stats                   datagrams and drops per direction since the last stats
  quit                    stop
"""

import argparse
import os
import random
import select
import socket
import struct
import sys
import time

HOST = "127.0.0.1"

NAMES = {0: "HEARTBEAT", 39: "MISSION_ITEM", 40: "MISSION_REQUEST", 41: "MISSION_SET_CURRENT", 42: "MISSION_CURRENT",
         43: "MISSION_REQUEST_LIST", 44: "MISSION_COUNT", 45: "MISSION_CLEAR_ALL", 46: "MISSION_ITEM_REACHED",
         47: "MISSION_ACK", 51: "MISSION_REQUEST_INT", 73: "MISSION_ITEM_INT", 76: "COMMAND_LONG", 77: "COMMAND_ACK",
         110: "FILE_TRANSFER_PROTOCOL", 148: "AUTOPILOT_VERSION", 253: "STATUSTEXT", 1: "SYS_STATUS", 2: "SYSTEM_TIME",
         24: "GPS_RAW_INT", 30: "ATTITUDE", 33: "GLOBAL_POSITION_INT", 62: "NAV_CONTROLLER_OUTPUT", 74: "VFR_HUD",
         65: "RC_CHANNELS", 36: "SERVO_OUTPUT_RAW", 66: "REQUEST_DATA_STREAM", 20: "PARAM_REQUEST_READ",
         21: "PARAM_REQUEST_LIST", 22: "PARAM_VALUE", 111: "TIMESYNC", 125: "POWER_STATUS", 152: "MEMINFO",
         163: "AHRS", 178: "AHRS2", 193: "EKF_STATUS_REPORT", 241: "VIBRATION", 242: "HOME_POSITION",
         147: "BATTERY_STATUS", 27: "RAW_IMU", 29: "SCALED_PRESSURE", 116: "SCALED_IMU2", 129: "SCALED_IMU3",
         137: "SCALED_PRESSURE2", 143: "SCALED_PRESSURE3", 136: "TERRAIN_REPORT", 133: "TERRAIN_REQUEST",
         230: "ESTIMATOR_STATUS", 165: "HWSTATUS", 168: "WIND", 11030: "ESC_TELEMETRY_1_TO_4", 32: "LOCAL_POSITION_NED",
         87: "POSITION_TARGET_GLOBAL_INT", 190: "MAG_CAL_REPORT", 191: "MAG_CAL_PROGRESS", 4: "PING",
         12920: "POWER_STATUS", 397: "COMPONENT_INFORMATION", 411: "CURRENT_EVENT_SEQUENCE", 0x5A: "HIL"}

MISSION_RESULTS = {0: "ACCEPTED", 1: "ERROR", 2: "UNSUPPORTED_FRAME", 3: "UNSUPPORTED", 4: "NO_SPACE", 5: "INVALID",
                   6: "INVALID_PARAM1", 13: "INVALID_SEQUENCE", 14: "DENIED", 15: "OPERATION_CANCELLED"}

FTP_OPS = {0: "None", 1: "TerminateSession", 2: "ResetSessions", 3: "ListDirectory", 4: "OpenFileRO", 5: "ReadFile",
           6: "CreateFile", 7: "WriteFile", 8: "RemoveFile", 9: "CreateDirectory", 10: "RemoveDirectory",
           11: "OpenFileWO", 12: "TruncateFile", 13: "Rename", 14: "CalcFileCRC32", 15: "BurstReadFile", 128: "ACK",
           129: "NAK"}

FTP_ERRORS = {0: "None", 1: "Fail", 2: "FailErrno", 3: "InvalidDataSize", 4: "InvalidSession", 5: "NoSessionsAvailable",
              6: "EOF", 7: "UnknownCommand", 8: "FileExists", 9: "FileProtected", 10: "FileNotFound"}

# messages whose passing is logged too: the transfers
FOLLOWED = {39, 40, 43, 44, 45, 47, 51, 73, 110, 253}


def frames(data):
    """(msgid, payload) of each MAVLink v1 or v2 frame in a datagram; payloads zero-extended by the caller."""
    i = 0
    while i < len(data):
        if data[i] == 0xFD and i + 10 <= len(data):
            n, incompat = data[i + 1], data[i + 2]
            msgid = data[i + 7] | data[i + 8] << 8 | data[i + 9] << 16
            yield msgid, data[i + 10:i + 10 + n]
            i += 12 + n + (13 if incompat & 1 else 0)
        elif data[i] == 0xFE and i + 6 <= len(data):
            n = data[i + 1]
            yield data[i + 5], data[i + 6:i + 6 + n]
            i += 8 + n
        else:
            i += 1     # not a frame start: resynchronise


def describe(msgid, payload):
    """The message's name, with the fields that say where a transfer is for the ones it follows."""
    name = NAMES.get(msgid, "msg%d" % msgid)
    p = bytes(payload) + bytes(max(0, 256 - len(payload)))  # MAVLink 2 trims trailing zeros
    if msgid in (40, 51):
        return "%s seq=%d" % (name, struct.unpack_from("<H", p, 0)[0])
    if msgid in (39, 73):
        return "%s seq=%d" % (name, struct.unpack_from("<H", p, 28)[0])
    if msgid == 44:
        return "%s count=%d" % (name, struct.unpack_from("<H", p, 0)[0])
    if msgid == 47:
        return "%s %s" % (name, MISSION_RESULTS.get(p[2], str(p[2])))
    if msgid == 253:
        return "%s '%s'" % (name, p[1:51].split(b"\0")[0].decode("ascii", "replace"))
    if msgid == 110:
        f = p[3:]
        seq, session, opcode, size, req = struct.unpack_from("<HBBBB", f, 0)
        offset = struct.unpack_from("<I", f, 8)[0]
        text = "FTP %s seq=%d s=%d ofs=%d size=%d" % (FTP_OPS.get(opcode, str(opcode)), seq, session, offset, size)
        if opcode in (128, 129):
            text += " req=%s" % FTP_OPS.get(req, str(req))
        if opcode == 129:
            text += " err=%s" % FTP_ERRORS.get(f[12], str(f[12]))
            if f[12] == 2:
                text += " errno=%d" % f[13]
        if f[6]:
            text += " burst_complete"
        return text
    return name


class Relay:

    def __init__(self, vehicle_port, gcs_port, relay_port, loss_up, loss_down, seed, log):
        self.vehicle_sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.vehicle_sock.bind((HOST, vehicle_port))
        self.gcs_sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.gcs_sock.bind((HOST, relay_port))
        self.vehicle_addr = None
        self.gcs_addr = (HOST, gcs_port)
        self.loss = {"up": loss_up, "down": loss_down}
        self.rng = {}
        self.reseed(seed)
        self.log = log
        self.start = time.monotonic()
        self.stats = {"up": [0, 0], "down": [0, 0], "ignored": 0}
        self.outage_until = None   # time.monotonic() until which everything is dropped
        self.drop_first = set()    # message ids whose next downlink datagram is dropped

    def reseed(self, seed):
        self.rng = {"up": random.Random(2 * seed), "down": random.Random(2 * seed + 1)}

    def write(self, line):
        if self.log:
            self.log.write("%.3f %s\n" % (time.monotonic() - self.start, line))

    def forward(self, direction, data, sock, dest):
        count = self.stats[direction]
        count[0] += 1
        dropped = self.loss[direction] > 0 and self.rng[direction].random() < self.loss[direction]
        if self.outage_until is not None:
            if time.monotonic() < self.outage_until:
                dropped = True
            else:
                self.write("mark outage over")
                self.outage_until = None
        msgs = [(m, p) for m, p in frames(data)]
        if direction == "down" and self.drop_first:
            first = self.drop_first.intersection(m for m, _ in msgs)
            if first:
                self.drop_first -= first
                dropped = True
        if dropped:
            count[1] += 1
            self.write("drop %s %s" % (direction, " | ".join(describe(m, p) for m, p in msgs)))
            return
        if any(m in FOLLOWED for m, _ in msgs):
            self.write("pass %s %s" % (direction, " | ".join(describe(m, p) for m, p in msgs)))
        try:
            sock.sendto(data, dest)
        except OSError as e:   # nobody listening yet: as a radio would, lose it
            self.write("unsent %s %s" % (direction, e))

    def command(self, line):
        words = line.split()
        if not words:
            return "ok"
        cmd, args = words[0], words[1:]
        if cmd == "loss" and len(args) in (1, 2):
            up = float(args[0])
            down = float(args[1]) if len(args) == 2 else up
            if not (0 <= up <= 1 and 0 <= down <= 1):
                return "error loss must be in [0, 1]"
            self.loss = {"up": up, "down": down}
            self.write("mark loss up %.3f down %.3f" % (up, down))
            return "ok loss %s %s" % (up, down)
        if cmd == "seed" and len(args) == 1:
            self.reseed(int(args[0]))
            self.write("mark seed %d" % int(args[0]))
            return "ok seed %d" % int(args[0])
        if cmd == "gcs" and len(args) == 1:
            self.gcs_addr = (HOST, int(args[0]))
            self.write("mark gcs %d" % int(args[0]))
            return "ok gcs %d" % int(args[0])
        if cmd == "mark":
            self.write("mark " + " ".join(args))
            return "ok"
        if cmd == "inject" and len(args) == 1:
            if self.vehicle_addr is None:
                return "error no vehicle yet"
            data = bytes.fromhex(args[0])
            self.write("inject up %s" % " | ".join(describe(m, p) for m, p in frames(data)))
            self.vehicle_sock.sendto(data, self.vehicle_addr)
            return "ok inject"
        if cmd == "outage" and len(args) == 1:
            self.outage_until = time.monotonic() + float(args[0])
            self.write("mark outage %g s" % float(args[0]))
            return "ok outage %g" % float(args[0])
        if cmd == "drop-first" and len(args) == 1:
            ids = [i for i, name in NAMES.items() if name == args[0].upper()]
            if not ids:
                return "error unknown message %s (known: %s)" % (args[0], ", ".join(sorted(set(NAMES.values()))))
            self.drop_first.update(ids)
            self.write("mark drop-first %s" % args[0].upper())
            return "ok drop-first %s" % args[0].upper()
        if cmd == "stats":
            s = self.stats
            answer = "ok up %d %d down %d %d ignored %d" % (s["up"][0], s["up"][1], s["down"][0], s["down"][1], s["ignored"])
            self.write("mark stats " + answer[3:])
            self.stats = {"up": [0, 0], "down": [0, 0], "ignored": 0}
            return answer
        return "error unknown command: " + line.strip()

    def run(self, control):
        inputs = [self.vehicle_sock, self.gcs_sock] + ([sys.stdin] if control else [])
        pending = b""
        while True:
            ready, _, _ = select.select(inputs, [], [])
            for r in ready:
                if r is self.vehicle_sock:
                    data, addr = self.vehicle_sock.recvfrom(65536)
                    if addr[0] != HOST:
                        continue
                    self.vehicle_addr = addr
                    self.forward("down", data, self.gcs_sock, self.gcs_addr)
                elif r is self.gcs_sock:
                    data, addr = self.gcs_sock.recvfrom(65536)
                    if addr != self.gcs_addr or self.vehicle_addr is None:
                        self.stats["ignored"] += 1
                        continue
                    self.forward("up", data, self.vehicle_sock, self.vehicle_addr)
                else:
                    chunk = os.read(sys.stdin.fileno(), 65536)   # not readline: select sees the fd, not Python's buffer
                    pending += chunk
                    while b"\n" in pending or not chunk:
                        line, _, pending = pending.partition(b"\n")
                        line = line.decode()
                        if line.strip() == "quit" or (not chunk and not line.strip()):
                            if self.log:
                                self.log.flush()
                            return
                        print(self.command(line), flush=True)
                    if self.log:
                        self.log.flush()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--vehicle-port", type=int, required=True, help="where the vehicle sends (SITL's udpclient port)")
    ap.add_argument("--gcs-port", type=int, required=True, help="where the ground station listens")
    ap.add_argument("--relay-port", type=int, default=0, help="the relay's own port towards the ground station")
    ap.add_argument("--loss", type=float, default=0.0, help="drop probability, both ways")
    ap.add_argument("--loss-up", type=float, help="drop probability ground station to vehicle")
    ap.add_argument("--loss-down", type=float, help="drop probability vehicle to ground station")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--log", help="the log of drops (and of transfer messages that passed)")
    ap.add_argument("--control", action="store_true", help="read commands on stdin")
    a = ap.parse_args()
    up = a.loss if a.loss_up is None else a.loss_up
    down = a.loss if a.loss_down is None else a.loss_down
    log = open(a.log, "a", buffering=1 << 16) if a.log else None
    relay = Relay(a.vehicle_port, a.gcs_port, a.relay_port, up, down, a.seed, log)
    print("ready vehicle %d relay %d gcs %d" % (a.vehicle_port, relay.gcs_sock.getsockname()[1], a.gcs_port), flush=True)
    try:
        relay.run(a.control)
    except KeyboardInterrupt:
        pass
    finally:
        if log:
            log.close()


if __name__ == "__main__":
    os.environ.setdefault("PYTHONUNBUFFERED", "1")
    main()
