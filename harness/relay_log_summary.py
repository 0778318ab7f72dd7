#!/usr/bin/env python3
"""What the uploads of harness/sitl_lossy_uploads.py did on the wire, from lossy_relay.py's logs.

  relay_log_summary.py RESULTS_DIR...

Splits each RESULTS_DIR/relay.log at the driver's marks ("round R loss L tool T seed S: upload" to
"...: verifying") and prints, per tool and loss level (summed over the rounds), a Markdown table of
the messages that mattered: MISSION_COUNTs and items sent (dropped or not), the vehicle's requests,
its MISSION_ACKs by result (INVALID_SEQUENCE, ERROR after the last item, ACCEPTED, ...), "Mission
upload timeout" STATUSTEXTs, FTP requests by opcode and NAKs by error, the FTP requests that passed
and were never answered, and the fate of the TerminateSessions that close a file created (dropped,
no reply, its ACK or NAK, that reply passed or dropped; a request sent again unchanged counts once).
"""

import collections
import re
import sys

MARK = re.compile(r"mark round (\d+) loss ([0-9.]+) tool (\S+) seed \d+: upload")
END = re.compile(r"mark round \d+ loss [0-9.]+ tool \S+: verifying")
NEXT = re.compile(r"mark round \d+ loss [0-9.]+ tool \S+ seed \d+: preparing")


def segments(path):
    """(tool, loss, [log lines], [lines after]) of each upload: its lines from the upload's mark to the
    verifying one, then the ones up to the next upload's preparation (late replies)."""
    current = None
    after = False
    with open(path) as f:
        for line in f:
            m = MARK.search(line)
            if m:
                current = (m.group(3), float(m.group(2)), [], [])
                after = False
            elif current and END.search(line):
                after = True
            elif current and NEXT.search(line):
                yield current
                current = None
            elif current:
                current[3 if after else 2].append(line.rstrip("\n"))
    if current:
        yield current


def ftp_fates(c, requests, replies):
    """Counts the FTP requests that passed and got no reply at all (the relay logs drops too, so the
    vehicle sent none), and what became of each TerminateSession closing a file created. A request
    sent again unchanged (same session and seq) counts once, as passed if one of its copies did."""
    created = {s for s, _, op, _ in requests if op == "CreateFile"}
    distinct = {}
    for session, seq, op, fate in requests:
        if distinct.get((session, seq, op)) != "pass":
            distinct[(session, seq, op)] = fate
    for (session, seq, op), fate in distinct.items():
        reply = replies.get((session, (seq + 1) % 65536, op))
        if fate == "pass" and reply is None:
            c["FTP %s passed, no reply" % op] += 1
        if op == "TerminateSession" and session in created:
            c["closing TerminateSession: " + ("dropped" if fate == "drop" else "no reply" if reply is None
                                              else "%s %s" % (reply[0], reply[1]))] += 1


def count(lines, after=()):
    """What the upload's lines show; the lines after it only give replies to its FTP requests."""
    c = collections.Counter()
    requests = []  # (session, seq, opcode, pass or drop) of FTP requests, in order
    replies = {}   # (session, seq, req opcode) -> (ACK or NAK (with its error), pass or drop)
    for line in lines:
        record(c, line, requests, replies)
    for line in after:
        record(collections.Counter(), line, [], replies)
    ftp_fates(c, requests, replies)
    return c


def record(c, line, requests, replies):
    """Counts one line of the relay's log into c, and its FTP requests and replies."""
    parts = line.split(" ", 3)
    if len(parts) < 4 or parts[1] not in ("pass", "drop"):
        return
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
            requests.append((field(words, "s"), int(field(words, "seq")), words[1], fate))
        elif name == "FTP" and words[1] in ("ACK", "NAK"):
            err = field(words, "err")
            if words[1] == "NAK":
                c["NAK %s %s" % (field(words, "req"), err or "?")] += 1
            key = (field(words, "s"), int(field(words, "seq")), field(words, "req"))
            if fate == "pass" or key not in replies:  # a reply repeated: did one get through
                replies[key] = (words[1] + (" " + err if err else ""), fate)


def field(words, key):
    """The value of key=value among a message's words, or None."""
    return next((w[len(key) + 1:] for w in words if w.startswith(key + "=")), None)


def main():
    cells = collections.defaultdict(collections.Counter)
    uploads = collections.Counter()
    for d in sys.argv[1:]:
        for tool, loss, lines, after in segments(d.rstrip("/") + "/relay.log"):
            cells[(tool, loss)].update(count(lines, after))
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
