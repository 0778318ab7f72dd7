#!/usr/bin/env python3
"""pymavlink's reading of our .waypoints files (MavwpInteropSpec, MissionCommandSpec).

Tests only: an independent reader to check dolphin.mavlink.mission.WaypointsFile against.

  mavwp_check.py FILE...
      Loads each file with pymavlink's mavwp.MAVWPLoader, the loader MAVProxy's "wp load" uses,
      and prints one JSON object per file and line:
        {"file", "count", "items": [{"seq", "current", "frame", "command", "param1", "param2",
         "param3", "param4", "x", "y", "z", "autocontinue", "mission_type"}, ...]}
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


def load(path):
    loader = mavwp.MAVWPLoader()
    count = loader.load(path)
    items = []
    for i in range(loader.count()):
        w = loader.wp(i)
        items.append({f: value(getattr(w, f)) for f in FIELDS})
    return {"file": path, "count": count, "items": items}


def main(argv):
    if not argv:
        print("usage: mavwp_check.py FILE...", file=sys.stderr)
        return 2
    assert mavutil.mavlink20(), "MAVLINK20 must be set before pymavlink is imported"
    for path in argv:
        try:
            result = load(path)
        except Exception as e:  # mavwp raises MAVWPError, ValueError, OSError
            print("mavwp could not load %s: %s: %s" % (path, type(e).__name__, e), file=sys.stderr)
            return 1
        print(json.dumps(result, allow_nan=False))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
