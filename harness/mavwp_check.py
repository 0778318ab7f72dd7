#!/usr/bin/env python3
"""pymavlink's reading of our .waypoints files (MavwpInteropSpec, MissionCommandSpec).

Tests only: an independent reader to check dolphin.mission.file.WaypointsFile against.

  mavwp_check.py [--fence | --rally] FILE...
      Loads each file with pymavlink's mavwp.MAVWPLoader, the loader MAVProxy's "wp load" uses,
      (--fence: MissionItemProtocol_Fence, "fence load"; --rally: MissionItemProtocol_Rally, "rally
      load", or for the legacy "RALLY lat lon alt ..." files MAVRallyLoader, whose heights stay in
      metres where MissionItemProtocol_Rally multiplies them by 1000) and prints one JSON object per
      file and line:
        {"file", "count", "units", "items": [{"seq", "current", "frame", "command", "param1", "param2",
         "param3", "param4", "x", "y", "z", "autocontinue", "mission_type"}, ...]}
      "units" says what x and y are: "degrees" (read from a QGC WPL line) or "degE7" (the legacy
      fence and rally loaders make integers, with int(): truncated, not rounded).
      Values are what mavwp made of the text (MISSION_ITEM fields, not yet packed: x and y are the
      degrees as Python floats). Non-finite floats, which JSON cannot carry, are the strings "NaN",
      "Infinity" and "-Infinity". A file mavwp rejects ends the run with exit 1 and its error.

mavwp's own quirks stay visible on purpose: it renumbers items 0, 1, ... in file order, and turns
a line-0 command 0 into NAV_WAYPOINT (Mission Planner's home).
"""

import json
import math
import os
import sys

os.environ["MAVLINK20"] = "1"

from pymavlink import mavutil, mavwp  # noqa: E402

FIELDS = ["seq", "current", "frame", "command", "param1", "param2", "param3", "param4", "x", "y", "z",
          "autocontinue", "mission_type"]


def value(v):
    if isinstance(v, float) and not math.isfinite(v):
        return "NaN" if math.isnan(v) else ("Infinity" if v > 0 else "-Infinity")
    return v


def load(path, kind):
    first = mavwp.get_first_line_from_file(path) or ""
    legacy = not first.startswith("QGC WPL")
    if kind == "rally" and legacy:
        loader = mavwp.MAVRallyLoader()
        loader.load(path)
        items = [{"seq": i, "current": 0, "frame": mavutil.mavlink.MAV_FRAME_GLOBAL_RELATIVE_ALT,
                  "command": mavutil.mavlink.MAV_CMD_NAV_RALLY_POINT, "param1": 0, "param2": 0, "param3": 0,
                  "param4": 0, "x": int(p.lat), "y": int(p.lng), "z": p.alt, "autocontinue": 0,
                  "mission_type": mavutil.mavlink.MAV_MISSION_TYPE_RALLY}
                 for i, p in enumerate(loader.rally_points)]
        return {"file": path, "count": len(items), "units": "degE7", "items": items}
    loader = {"mission": mavwp.MAVWPLoader, "fence": mavwp.MissionItemProtocol_Fence,
              "rally": mavwp.MissionItemProtocol_Rally}[kind]()
    loader.load(path)
    items = []
    for i in range(loader.count()):
        w = loader.wp(i)
        items.append({f: value(getattr(w, f)) for f in FIELDS})
    return {"file": path, "count": loader.count(), "units": "degE7" if legacy else "degrees", "items": items}


def main(argv):
    kind = "mission"
    if argv and argv[0] in ("--fence", "--rally"):
        kind = argv[0][2:]
        argv = argv[1:]
    if not argv:
        print("usage: mavwp_check.py [--fence | --rally] FILE...", file=sys.stderr)
        return 2
    assert mavutil.mavlink20(), "MAVLINK20 must be set before pymavlink is imported"
    for path in argv:
        try:
            result = load(path, kind)
        except Exception as e:  # mavwp raises MAVWPError, ValueError, OSError
            print("mavwp could not load %s: %s: %s" % (path, type(e).__name__, e), file=sys.stderr)
            return 1
        print(json.dumps(result, allow_nan=False))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
