#!/usr/bin/env python3
"""Injects one fault into ArduPilot SITL mid-mission, as ArduPilot's own autotest does, and logs what
the vehicle says and does. A harness tool (pymavlink), never a runtime dependency; harness/sitl-faults.sh
starts it beside SITL and dolphin, inside a network namespace with only loopback.

  fault_injector.py --link udpin:127.0.0.1:PORT --fault FAULT [--after-seq N] [--vehicle copter|plane|rover]
                    [--hold S] [--rcin-port P] [--wind-speed MPS] [--outage S --relay-control FIFO] [--timeout S] [--log FILE]

It is a second ground station on its own link (SITL's --serial1 udpclient:127.0.0.1:PORT), system 250
("a safety pilot"), component 190. It asks for the streams it reads on that link only, waits until the
vehicle is armed in AUTO with MISSION_CURRENT seq >= N, then injects FAULT once:

  motor   PARAM_SET SIM_ENGINE_MUL 0 and SIM_ENGINE_FAIL 1 (servo 1: a copter's motor 1; a plane's
          throttle is servo 3, so --vehicle plane sets SIM_ENGINE_FAIL 4), as Tools/autotest/arducopter.py
          does (libraries/AP_HAL_SITL/SITL_State.cpp scales the masked servos' output by SIM_ENGINE_MUL)
  gps     PARAM_SET SIM_GPS1_ENABLE 0 (SIM_GPS_DISABLE in older trees)
  pause   MAV_CMD_DO_SET_MODE to LOITER (rover: HOLD), --hold S seconds (default 15), then AUTO. A copter's
          LOITER follows the pilot's throttle stick, which SITL's RC input leaves at 1000 (descend at full
          rate: it lands and disarms), so for a copter the pilot first centres it as the autotest does
          (set_rc(3, 1500)): the RC channels SITL reports, throttle 1500, sent to SITL's RC input port
          (--rcin-port: 5501 + 10 x instance, 5801 for -I30), and puts it back after AUTO
  stall   PARAM_SET SIM_WIND_T 1 (no fall-off near the ground), SIM_WIND_DIR to the bearing of the
          current target (NAV_CONTROLLER_OUTPUT.target_bearing: the wind blows from the waypoint) and
          SIM_WIND_SPD --wind-speed (default 30 m/s)
  outage  no injection on the vehicle: writes "outage S" to the control FIFO of harness/lossy_relay.py,
          which drops everything both ways between SITL and dolphin for S seconds (default 30)
  none    nothing: only the log

The log has one line per event: the wall clock (HH:MM:SS.mmm), the vehicle's time since boot (s, from the
last time_boot_ms seen), after the injection the offsets from it in wall and boot seconds, then the event:
every STATUSTEXT (with its severity), each change of HEARTBEAT mode or armed state, of
EXTENDED_SYS_STATE landed state, of MISSION_CURRENT, and what the injector sent and the answers
(PARAM_VALUE, COMMAND_ACK). It ends by itself after --timeout seconds (default 300), or 20 s after the
vehicle disarmed following the injection.
"""

import argparse
import datetime
import os
import signal
import socket
import struct
import sys
import time

os.environ["MAVLINK20"] = "1"

from pymavlink import mavutil  # noqa: E402

mavlink = mavutil.mavlink

SEVERITY = {0: "EMERGENCY", 1: "ALERT", 2: "CRITICAL", 3: "ERROR", 4: "WARNING", 5: "NOTICE", 6: "INFO",
            7: "DEBUG"}
LANDED = {0: "UNDEFINED", 1: "ON_GROUND", 2: "IN_AIR", 3: "TAKEOFF", 4: "LANDING"}
# custom modes, by ArduPilot family
MODES = {
    "copter": {0: "STABILIZE", 2: "ALT_HOLD", 3: "AUTO", 4: "GUIDED", 5: "LOITER", 6: "RTL", 9: "LAND",
               16: "POSHOLD", 17: "BRAKE", 21: "SMART_RTL"},
    "plane": {0: "MANUAL", 5: "FLY_BY_WIRE_A", 10: "AUTO", 11: "RTL", 12: "LOITER", 15: "GUIDED", 18: "THERMAL"},
    "rover": {0: "MANUAL", 4: "HOLD", 5: "LOITER", 10: "AUTO", 11: "RTL", 12: "SMART_RTL", 15: "GUIDED"},
}
AUTO = {"copter": 3, "plane": 10, "rover": 10}
PAUSE = {"copter": 5, "plane": 12, "rover": 4}   # LOITER, LOITER, HOLD
VEHICLE_SYSID = 1


class Injector:
    def __init__(self, args):
        self.args = args
        self.link = mavutil.mavlink_connection(args.link, source_system=250, source_component=190)
        self.log = open(args.log, "a", buffering=1) if args.log else sys.stdout
        self.boot_s = 0.0
        self.injected = None          # (wall, boot) of the injection
        self.mode = self.armed = self.landed = self.seq = None
        self.target_bearing = None
        self.disarmed_at = None
        self.resume_at = None         # pause: when to send AUTO again
        self.outage_end = None        # outage: when the relay lets datagrams through again
        self.stop = False
        self.rc = None                # the vehicle's RC_CHANNELS 1..8 as last seen
        self.rc_sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)

    def send_rc(self, throttle):
        """SITL's RC input (AP_RCProtocol_UDP): 8 uint16 PWM values; SITL keeps the last ones sent."""
        pwm = list(self.rc)
        pwm[2] = throttle
        self.write("inject RC input %s (throttle %d)" % (pwm, throttle))
        for _ in range(3):
            self.rc_sock.sendto(struct.pack("<8H", *pwm), ("127.0.0.1", self.args.rcin_port))

    def write(self, event):
        now = time.time()
        clock = datetime.datetime.fromtimestamp(now).strftime("%H:%M:%S.%f")[:-3]
        offsets = ""
        if self.injected:
            offsets = " +%7.3f wall +%7.3f boot" % (now - self.injected[0], self.boot_s - self.injected[1])
        self.log.write("%s boot %8.3f%s  %s\n" % (clock, self.boot_s, offsets, event))
        self.log.flush()

    def mode_name(self, custom):
        return MODES[self.args.vehicle].get(custom, "mode %d" % custom)

    def set_param(self, name, value):
        self.write("inject PARAM_SET %s %s" % (name, value))
        self.link.mav.param_set_send(VEHICLE_SYSID, 1, name.encode(), float(value), mavlink.MAV_PARAM_TYPE_REAL32)

    def set_mode(self, custom):
        self.write("inject MAV_CMD_DO_SET_MODE %s" % self.mode_name(custom))
        self.link.mav.command_long_send(VEHICLE_SYSID, 1, mavlink.MAV_CMD_DO_SET_MODE, 0,
                                        mavlink.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED, custom, 0, 0, 0, 0, 0)

    def ask_streams(self):
        """The streams this link needs, on this link only (ArduPilot keeps rates per channel)."""
        self.link.mav.request_data_stream_send(VEHICLE_SYSID, 1, mavlink.MAV_DATA_STREAM_ALL, 4, 1)
        for msg_id, hz in ((mavlink.MAVLINK_MSG_ID_EXTENDED_SYS_STATE, 4), (mavlink.MAVLINK_MSG_ID_MISSION_CURRENT, 4),
                           (mavlink.MAVLINK_MSG_ID_NAV_CONTROLLER_OUTPUT, 4), (mavlink.MAVLINK_MSG_ID_SYSTEM_TIME, 4)):
            self.link.mav.command_long_send(VEHICLE_SYSID, 1, mavlink.MAV_CMD_SET_MESSAGE_INTERVAL, 0,
                                            msg_id, 1e6 / hz, 0, 0, 0, 0, 0)

    def inject(self):
        a = self.args
        self.injected = (time.time(), self.boot_s)
        self.write("injection: %s at MISSION_CURRENT seq %s, %s" % (a.fault, self.seq, self.mode_name(self.mode)))
        if a.fault == "motor":
            self.set_param("SIM_ENGINE_MUL", 0)
            self.set_param("SIM_ENGINE_FAIL", 4 if a.vehicle == "plane" else 1)
        elif a.fault == "gps":
            self.set_param("SIM_GPS1_ENABLE", 0)
        elif a.fault == "pause":
            if a.vehicle == "copter":
                self.rc_throttle = self.rc[2]
                self.send_rc(1500)
                time.sleep(0.1)
            self.set_mode(PAUSE[a.vehicle])
            self.resume_at = time.time() + a.hold
        elif a.fault == "stall":
            bearing = self.target_bearing if self.target_bearing is not None else 0
            self.set_param("SIM_WIND_T", 1)
            self.set_param("SIM_WIND_DIR", bearing)
            self.set_param("SIM_WIND_SPD", a.wind_speed)
        elif a.fault == "outage":
            with open(a.relay_control, "w") as fifo:
                fifo.write("outage %g\n" % a.outage)
            self.write("inject relay outage %g s (both ways)" % a.outage)
            self.outage_end = time.time() + a.outage

    def handle(self, m):
        t = m.get_type()
        if hasattr(m, "time_boot_ms") and m.get_srcSystem() == VEHICLE_SYSID:
            self.boot_s = m.time_boot_ms / 1000.0
        if m.get_srcSystem() != VEHICLE_SYSID:
            return
        if t == "HEARTBEAT" and m.get_srcComponent() == 1:
            armed = bool(m.base_mode & mavlink.MAV_MODE_FLAG_SAFETY_ARMED)
            if (m.custom_mode, armed) != (self.mode, self.armed):
                self.write("HEARTBEAT %s %s" % (self.mode_name(m.custom_mode), "armed" if armed else "disarmed"))
                if self.injected and self.armed and not armed:
                    self.disarmed_at = time.time()
                self.mode, self.armed = m.custom_mode, armed
        elif t == "STATUSTEXT":
            self.write("STATUSTEXT %s '%s'" % (SEVERITY.get(m.severity, m.severity), m.text))
        elif t == "EXTENDED_SYS_STATE":
            if m.landed_state != self.landed:
                self.write("EXTENDED_SYS_STATE landed_state %s" % LANDED.get(m.landed_state, m.landed_state))
                self.landed = m.landed_state
        elif t == "MISSION_CURRENT":
            if m.seq != self.seq:
                self.write("MISSION_CURRENT seq %d of %d" % (m.seq, m.total))
                self.seq = m.seq
        elif t == "RC_CHANNELS":
            self.rc = [getattr(m, "chan%d_raw" % i) for i in range(1, 9)]
        elif t == "NAV_CONTROLLER_OUTPUT":
            self.target_bearing = m.target_bearing % 360
        elif t == "PARAM_VALUE" and m.param_id.startswith("SIM_"):
            self.write("PARAM_VALUE %s %g" % (m.param_id, m.param_value))
        elif t == "COMMAND_ACK" and m.command == mavlink.MAV_CMD_DO_SET_MODE:
            self.write("COMMAND_ACK DO_SET_MODE result %d" % m.result)

    def run(self):
        a = self.args
        deadline = time.time() + a.timeout
        self.write("waiting for the vehicle on %s (fault %s after MISSION_CURRENT seq %d)" % (a.link, a.fault, a.after_seq))
        next_heartbeat = 0.0
        while not self.stop and time.time() < deadline:
            now = time.time()
            if now >= next_heartbeat:
                # a ground station's heartbeat, so that ArduPilot keeps this link's streams going
                self.link.mav.heartbeat_send(mavlink.MAV_TYPE_GCS, mavlink.MAV_AUTOPILOT_INVALID, 0, 0, 0)
                if self.mode is not None and self.injected is None:
                    self.ask_streams()   # again now and then: SITL may have started after us
                next_heartbeat = now + 1.0
            m = self.link.recv_match(blocking=True, timeout=0.1)
            if m is not None and m.get_type() != "BAD_DATA":
                self.handle(m)
            if (self.injected is None and self.armed and self.mode == AUTO[a.vehicle] and self.seq is not None
                    and self.seq >= a.after_seq and (a.fault != "stall" or self.target_bearing is not None)
                    and (a.fault != "pause" or self.rc is not None)):
                self.inject()
            if self.resume_at and time.time() >= self.resume_at:
                self.resume_at = None
                self.set_mode(AUTO[a.vehicle])
                if a.vehicle == "copter":
                    self.send_rc(self.rc_throttle)
            if self.outage_end and time.time() >= self.outage_end:
                self.outage_end = None
                self.write("relay outage over: the relay passes datagrams again")
            if self.disarmed_at and time.time() > self.disarmed_at + 20:
                self.write("disarmed 20 s ago: done")
                return
        self.write("stopped" if self.stop else "timeout after %d s: done" % a.timeout)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--link", required=True, help="pymavlink connection string, e.g. udpin:127.0.0.1:14590")
    ap.add_argument("--fault", required=True, choices=["motor", "gps", "pause", "stall", "outage", "none"])
    ap.add_argument("--after-seq", type=int, default=4, help="inject once MISSION_CURRENT seq >= N in AUTO")
    ap.add_argument("--vehicle", default="copter", choices=sorted(MODES))
    ap.add_argument("--hold", type=float, default=15, help="pause: seconds in LOITER/HOLD before AUTO")
    ap.add_argument("--rcin-port", type=int, default=5801, help="pause: SITL's RC input port (5501 + 10 x -I)")
    ap.add_argument("--wind-speed", type=float, default=30, help="stall: SIM_WIND_SPD, m/s")
    ap.add_argument("--outage", type=float, default=30, help="outage: seconds of total loss")
    ap.add_argument("--relay-control", help="outage: lossy_relay.py's control FIFO")
    ap.add_argument("--timeout", type=float, default=300, help="stop after this many seconds in any case")
    ap.add_argument("--log", help="append the log here (default: standard output)")
    args = ap.parse_args()
    if args.fault == "outage" and not args.relay_control:
        ap.error("--fault outage needs --relay-control")
    injector = Injector(args)
    signal.signal(signal.SIGTERM, lambda *_: setattr(injector, "stop", True))
    injector.run()


if __name__ == "__main__":
    main()
