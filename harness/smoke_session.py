#!/usr/bin/env python3
"""A pymavlink ground station for ArduCopter SITL running src/test/resources/lua/smoke-plume.lua
(harness/record-smoke-plume.sh starts both). Not a test: it records copter-smoke-plume.tlog and
prints what it saw, one line per event.

  smoke_session.py PORT [--tlog FILE] [--fly]

Listens with mavutil.mavlink_connection('udpin:127.0.0.1:PORT') as system 208, component 190 (as
dolphin does), sends a HEARTBEAT each second, and:
  1. after the autopilot's first heartbeat, sends COMMAND_LONG MAV_CMD_REQUEST_MESSAGE (512) for
     CAMERA_INFORMATION (259), then GIMBAL_MANAGER_INFORMATION (280), to component 1, and prints
     the COMMAND_ACK and every answer that comes within 2 s;
  2. asks for GLOBAL_POSITION_INT at 4 Hz (MAV_CMD_SET_MESSAGE_INTERVAL) and prints the SMOKE
     NAMED_VALUE_FLOATs: sender, name as on the wire, time_boot_ms spacing;
  3. with --fly: GUIDED, arms (retrying until the EKF uses GPS), takes off to 30 m, flies to the
     plume's centre with SET_POSITION_TARGET_GLOBAL_INT, on to 100 m north of it, then RTL until
     it has landed and disarmed.
--tlog FILE writes every frame in and out as dolphin's --tlog does: an 8-byte big-endian Unix
time in microseconds, then the frame.
"""

import argparse
import math
import os
import struct
import time

os.environ["MAVLINK20"] = "1"

from pymavlink import mavutil  # noqa: E402

mavlink = mavutil.mavlink
CENTRE = (40.4461, -7.3752)  # the plume's centre in smoke-plume.lua
METRES_PER_DEGREE = 111319.49


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("port", type=int)
    parser.add_argument("--tlog")
    parser.add_argument("--fly", action="store_true")
    args = parser.parse_args()
    Session(args.port, args.tlog).run(args.fly)


class Session:
    def __init__(self, port, tlog):
        self.link = mavutil.mavlink_connection(f"udpin:127.0.0.1:{port}", source_system=208,
                                               source_component=190)
        self.tlog = open(tlog, "wb") if tlog else None
        self.link.mav.set_send_callback(lambda msg, *_: self.record(msg.get_msgbuf()))
        self.start = time.time()
        self.next_heartbeat = 0.0
        self.boot_ms = 0
        self.heartbeats = {}
        self.smoke = []
        self.position = None
        self.disarmed = False

    def record(self, frame):
        if self.tlog:
            self.tlog.write(struct.pack(">Q", int(time.time() * 1e6)) + bytes(frame))

    def say(self, *words):
        print(f"[{time.time() - self.start:7.2f} s, boot {self.boot_ms / 1000:7.2f} s]", *words,
              flush=True)

    def pump(self, timeout=0.1):
        if time.time() >= self.next_heartbeat and self.heartbeats:
            self.link.mav.heartbeat_send(mavlink.MAV_TYPE_GCS, mavlink.MAV_AUTOPILOT_INVALID, 0, 0, 0)
            self.next_heartbeat = time.time() + 1.0
        msg = self.link.recv_match(blocking=True, timeout=timeout)
        if msg is None or msg.get_type() == "BAD_DATA":
            return None
        self.record(msg.get_msgbuf())
        kind, source = msg.get_type(), (msg.get_srcSystem(), msg.get_srcComponent())
        if source == (1, 1) and hasattr(msg, "time_boot_ms"):
            self.boot_ms = msg.time_boot_ms
        if kind == "HEARTBEAT":
            if source not in self.heartbeats:
                self.say("first HEARTBEAT from", source, "type", msg.type, "autopilot", msg.autopilot)
            self.heartbeats[source] = self.heartbeats.get(source, 0) + 1
        elif kind == "NAMED_VALUE_FLOAT":
            # MAVLink 2 drops the payload's trailing zeros: the name is as long as it was sent
            length = msg._header.mlen
            name_on_wire = bytes(msg.get_msgbuf()[10 + 8:10 + length])
            self.smoke.append((msg.time_boot_ms, msg.value))
            if len(self.smoke) <= 2 or len(self.smoke) % 10 == 0 or 0 < msg.value:
                self.say("NAMED_VALUE_FLOAT from", source, repr(msg.name), "payload", length,
                         "bytes, name on the wire", name_on_wire, "time_boot_ms", msg.time_boot_ms,
                         "value", round(msg.value, 3), "at", self.distance(), "m from the centre")
        elif kind == "GLOBAL_POSITION_INT":
            self.position = msg
        elif kind == "STATUSTEXT":
            self.say("STATUSTEXT", msg.text)
            self.disarmed = self.disarmed or msg.text == "Disarming motors"
        return msg

    def distance(self):
        if self.position is None:
            return None
        north = (self.position.lat / 1e7 - CENTRE[0]) * METRES_PER_DEGREE
        east = ((self.position.lon / 1e7 - CENTRE[1]) * METRES_PER_DEGREE
                * math.cos(math.radians(CENTRE[0])))
        return round(math.hypot(north, east), 1)

    def wait(self, until, seconds):
        end = time.time() + seconds
        while time.time() < end:
            msg = self.pump()
            if msg is not None and until(msg):
                return msg
        return None

    def command(self, command, *params, answers=(), seconds=2.0):
        """COMMAND_LONG to (1, 1); returns its COMMAND_ACK result, and what `answers` names came
        within the seconds (without answers to wait for, returns on the ACK)."""
        params = list(params) + [0] * (7 - len(params))
        sent = time.time()
        self.link.mav.command_long_send(1, 1, command, 0, *params)
        result, got = None, []
        while time.time() < sent + seconds:
            msg = self.pump()
            if msg is None:
                continue
            if msg.get_type() == "COMMAND_ACK" and msg.command == command and result is None:
                result = msg.result
                self.say("COMMAND_ACK", command, "result", result, "from",
                         (msg.get_srcSystem(), msg.get_srcComponent()),
                         "after", round(time.time() - sent, 3), "s")
                if not answers:
                    break
            if msg.get_type() in answers:
                got.append(msg)
                self.say(msg.get_type(), "from", (msg.get_srcSystem(), msg.get_srcComponent()),
                         msg.to_dict())
        return result, got

    def goto(self, lat, lon):
        self.link.mav.set_position_target_global_int_send(
            0, 1, 1, mavlink.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, 0b0000111111111000,
            int(lat * 1e7), int(lon * 1e7), 30, 0, 0, 0, 0, 0, 0, 0, 0)

    def run(self, fly):
        self.wait(lambda m: m.get_type() == "HEARTBEAT" and m.get_srcComponent() == 1, 30)
        for message_id, name in ((259, "CAMERA_INFORMATION"), (280, "GIMBAL_MANAGER_INFORMATION")):
            _, got = self.command(mavlink.MAV_CMD_REQUEST_MESSAGE, message_id, answers=(name,))
            if not got:
                self.say("no", name, "within 2 s")
        self.command(mavlink.MAV_CMD_SET_MESSAGE_INTERVAL, 33, 250000)
        self.wait(lambda m: False, 3.0)
        if fly:
            self.fly()
        spacing = [b[0] - a[0] for a, b in zip(self.smoke, self.smoke[1:])]
        if spacing:
            self.say(len(self.smoke), "SMOKE; time_boot_ms spacing min", min(spacing), "max",
                     max(spacing), "mean", round(sum(spacing) / len(spacing), 1), "; highest value",
                     round(max(v for _, v in self.smoke), 3))
        self.say("heartbeats by (system, component):", self.heartbeats)
        if self.tlog:
            self.tlog.close()

    def fly(self):
        for _ in range(30):
            if self.command(mavlink.MAV_CMD_DO_SET_MODE, 1, 4)[0] == 0:
                break
        for _ in range(60):
            if self.command(mavlink.MAV_CMD_COMPONENT_ARM_DISARM, 1)[0] == 0:
                break
            self.wait(lambda m: False, 1.0)
        self.command(mavlink.MAV_CMD_NAV_TAKEOFF, 0, 0, 0, 0, 0, 0, 30)
        self.wait(lambda m: m.get_type() == "GLOBAL_POSITION_INT" and m.relative_alt > 29000, 60)
        self.say("at 30 m,", self.distance(), "m from the centre; to the centre")
        self.goto(*CENTRE)
        self.wait(lambda m: m.get_type() == "GLOBAL_POSITION_INT" and self.distance() < 1.0, 60)
        self.say("over the centre,", self.distance(), "m from it")
        self.wait(lambda m: False, 2.0)
        self.goto(CENTRE[0] + 100 / METRES_PER_DEGREE, CENTRE[1])
        self.wait(lambda m: m.get_type() == "GLOBAL_POSITION_INT" and self.distance() > 99, 30)
        self.say("100 m north of the centre; RTL")
        self.command(mavlink.MAV_CMD_DO_SET_MODE, 1, 6)
        self.wait(lambda m: self.disarmed, 90)


if __name__ == "__main__":
    main()
