#!/usr/bin/env python3
"""What the uploads of harness/sitl_lossy_uploads.py did on the wire, from lossy_relay.py's logs.

  relay_log_summary.py RESULTS_DIR...

Splits each RESULTS_DIR/relay.log at the driver's marks ("round R loss L tool T seed S: upload" to
"...: verifying") and prints, per tool and loss level (summed over the rounds), a Markdown table of
the messages that mattered: MISSION_COUNTs and items sent (dropped or not), the vehicle's requests,
its MISSION_ACKs by result (INVALID_SEQUENCE, ERROR after the last item, ACCEPTED, ...), "Mission
upload timeout" STATUSTEXTs, FTP requests by opcode and NAKs by error.
"""

import collections
import re
import sys

MARK = re.compile(r"mark round (\d+) loss ([0-9.]+) tool (\S+) seed \d+: upload")
END = re.compile(r"mark round \d+ loss [0-9.]+ tool \S+: verifying")


def segments(path):
    """(tool, loss, [log lines]) of each upload."""
    current = None
    with open(path) as f:
        for line in f:
            m = MARK.search(line)
            if m:
                current = (m.group(3), float(m.group(2)), [])
                continue
            if current and END.search(line):
                yield current
                current = None
                continue
            if current:
                current[2].append(line.rstrip("\n"))


def count(lines):
    c = collections.Counter()
    for line in lines:
        parts = line.split(" ", 3)
        if len(parts) < 4 or parts[1] not in ("pass", "drop"):
            continue
        fate, direction, body = parts[1], parts[2], parts[3]
        for msg in body.split(" | "):
            words = msg.split()
            name = words[0]
            if name in ("MISSION_COUNT",):
                c["count sent"] += 1
                c["count dropped"] += fate == "drop"
            elif name in ("MISSION_ITEM_INT", "MISSION_ITEM") and direction == "up":
                c["items sent"] += 1
                c["items dropped"] += fate == "drop"
            elif name in ("MISSION_REQUEST_INT", "MISSION_REQUEST") and direction == "down":
                c["requests"] += 1
                c["requests dropped"] += fate == "drop"
            elif name == "MISSION_ACK" and direction == "down":
                c["ACK " + words[1]] += 1
                c["ACK %s dropped" % words[1]] += fate == "drop"
            elif name == "STATUSTEXT" and "upload timeout" in msg:
                c["'Mission upload timeout'"] += 1
            elif name == "FTP" and direction == "up":
                c["FTP " + words[1]] += 1
                c["FTP %s dropped" % words[1]] += fate == "drop"
            elif name == "FTP" and words[1] == "NAK":
                err = [w for w in words if w.startswith("err=")]
                c["NAK %s %s" % ([w[4:] for w in words if w.startswith("req=")][0], err[0][4:] if err else "?")] += 1
    return c


def main():
    cells = collections.defaultdict(collections.Counter)
    uploads = collections.Counter()
    for d in sys.argv[1:]:
        for tool, loss, lines in segments(d.rstrip("/") + "/relay.log"):
            cells[(tool, loss)].update(count(lines))
            uploads[(tool, loss)] += 1
    for tool in sorted({t for t, _ in cells}):
        losses = sorted(l for t, l in cells if t == tool)
        keys = sorted({k for (t, _), c in cells.items() if t == tool for k, v in c.items() if v})
        print("\n### %s (sums over the uploads)\n" % tool)
        print("| | " + " | ".join("%d %% (%d)" % (round(l * 100), uploads[(tool, l)]) for l in losses) + " |")
        print("|---|" + "---|" * len(losses))
        for k in keys:
            print("| %s | " % k + " | ".join(str(cells[(tool, l)][k]) for l in losses) + " |")


if __name__ == "__main__":
    main()
