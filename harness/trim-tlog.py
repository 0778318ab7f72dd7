"""Cuts a SITL recording (harness/record-sitl.sh's tlog) down to the frames its readers use, so that it
stays small in the repository: every frame of the ground station (system 208) and, of the vehicles'
frames, only the message kinds named in KEPT. Frames are copied byte for byte with their timestamps.
ArduPilot streams dozens of other kinds (ATTITUDE, SIMSTATE, NAMED_VALUE_FLOAT, ...) that no spec reads.

    .venv/bin/python harness/trim-tlog.py RECORDING.tlog      (rewrites it in place)

--since SECONDS keeps only the frames from that many seconds after the first one, and --vehicle N only the
frames of system N besides the ground station's: to cut one feature's vehicle out of a SITL spec's whole
tlog (SITL_TLOG_DIR).
"""
import argparse
import sys

from pymavlink.dialects.v20 import ardupilotmega as mavlink

GROUND_STATION = 208
KEPT = {
    "HEARTBEAT", "SYS_STATUS", "GPS_RAW_INT", "GLOBAL_POSITION_INT", "EKF_STATUS_REPORT", "HOME_POSITION",
    "GPS_GLOBAL_ORIGIN", "EXTENDED_SYS_STATE", "STATUSTEXT", "COMMAND_LONG", "COMMAND_INT", "COMMAND_ACK",
    "MISSION_COUNT", "MISSION_REQUEST", "MISSION_REQUEST_INT", "MISSION_REQUEST_LIST", "MISSION_ITEM",
    "MISSION_ITEM_INT", "MISSION_ACK", "MISSION_CLEAR_ALL", "MISSION_SET_CURRENT", "MISSION_CURRENT",
    "MISSION_ITEM_REACHED", "PARAM_VALUE", "PARAM_REQUEST_READ", "PARAM_REQUEST_LIST", "PARAM_SET",
}
KEPT_IDS = {msg_id for msg_id, cls in mavlink.mavlink_map.items() if cls.msgname in KEPT}
TIMESTAMP = 8


def frames(data):
    """(timestamp and frame bytes, system id, message id) for each record of the tlog."""
    i = 0
    # a timestamp without its frame at the end: dolphin was stopped (timeout) between writing the two
    while i + TIMESTAMP < len(data):
        start = i + TIMESTAMP
        magic, length = data[start], data[start + 1]
        if magic == 0xFD:
            signed = 13 if data[start + 2] & 0x01 else 0
            end = start + 10 + length + 2 + signed
            system, msg_id = data[start + 5], int.from_bytes(data[start + 7:start + 10], "little")
        elif magic == 0xFE:
            end = start + 6 + length + 2
            system, msg_id = data[start + 3], data[start + 5]
        else:
            sys.exit(f"not a MAVLink frame at byte {start} (magic {magic:#x})")
        yield data[i:end], system, msg_id
        i = end


def micros(record):
    """The record's timestamp: microseconds since 1970, big-endian, before its frame."""
    return int.from_bytes(record[:TIMESTAMP], "big")


def main(path, since=0.0, vehicle=None):
    data = open(path, "rb").read()
    records = list(frames(data))
    start = micros(records[0][0]) + since * 1e6 if records else 0
    kept = [record for record, system, msg_id in records
            if micros(record) >= start
            and (system == GROUND_STATION or msg_id in KEPT_IDS and vehicle in (None, system))]
    with open(path, "wb") as out:
        out.write(b"".join(kept))
    print(f"{path}: {len(records)} frames, {len(kept)} kept, {len(data)} bytes before, {sum(map(len, kept))} after")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description="Cuts a SITL recording down to the frames its readers use.")
    parser.add_argument("tlog")
    parser.add_argument("--since", type=float, default=0.0, help="seconds after the first frame to keep from")
    parser.add_argument("--vehicle", type=int, help="the one vehicle (system id) whose frames to keep")
    args = parser.parse_args()
    main(args.tlog, args.since, args.vehicle)
