#!/usr/bin/env python3
"""A SiK telemetry radio pair (or one ground radio and several vehicle radios) as a relay on 127.0.0.1.

  sik_radio.py --vehicle-port V [--vehicle-port V2 ...] (--gcs-port G [--relay-port R] | --gcs-pty LINK)
               [--profile sik|worse|clear] [--seed S] [--log FILE] [--control] [--air-rate 64]
               [--serial-baud 57600] [--fixed-window-counter] [--stats-interval 1]

A drop-in alternative to harness/lossy_relay.py (same ports, same "ready ..." line, same --control
commands where they make sense): the vehicle (ArduPilot SITL with --serial0 udpclient:127.0.0.1:V)
sends to V; the ground station listens on 127.0.0.1:G and sends back to R, or opens the
pseudo-terminal linked at LINK as a serial port at 57600 (our runtime: serial:LINK:57600). Every
socket is bound to 127.0.0.1 and sends only there.

What is modelled, and from which file of the SiK firmware (github.com/ArduPilot/SiK, Firmware/radio):

- Serial side (serial.c, packet.c's packet_set_serial_speed): each host talks to its radio at the
  serial baud (57600 8N1: 5760 bytes/s), both ways, whatever the host side is (UDP or pty). Bytes from
  the host enter a buffer of 1850 bytes (serial.c's RX_BUFF_MAX; a ring that holds 1849): a byte
  arriving when it is full is thrown away (serial_interrupt), so frames reach the far end truncated.
  Bytes from the air go to a 645-byte buffer (TX_BUFF_MAX) on their way to the host: serial_write_buf
  keeps what fits of an air packet and throws the rest away.
- Time division (tdm.c): tdm_init's timings, from the air rate: ticks of 16 us, ticks_per_byte, a
  packet latency, a silence of two latencies, a transmit window for three full packets (7140 ticks,
  114 ms, at 64 kbps; silence 4.2 ms). The radios take turns: window, silence, other window,
  silence. In its window a radio asks packet_get_next for as much as fits in the time left
  (tdm_serial_loop's max_xmit); when that returns nothing it sends a zero-length packet and yields
  the rest of its window (transmit_yield), and the other radio, on hearing it, may send in that
  window (bonus_transmit, sync_tx_windows). A radio that has yielded stays silent until the window
  ends, however much data arrives meanwhile. Every 0.5 s (link_update) a radio with nothing to send
  sends a statistics packet instead of yielding (its RSSI and noise become the other's remrssi and
  remnoise).
- The 8-bit window counter (tdm_serial_loop; SiK pull request 97, not merged): max_xmit is a uint8_t
  assigned (tdm_state_remaining - packet_latency) / ticks_per_byte, up to 775 at 64 kbps, so it wraps:
  it is below 18 (nothing sent, the radio waits) for 2.6 ms of every 37 ms, and otherwise any value
  from 18 to 255 by where in the window the radio is. With MAVLink framing a frame that does not fit
  the wrapped value is not sent: mavlink_frame returns nothing, packet_get_next returns 0, and the
  radio yields the rest of its window with the frame still queued. A frame of 200 bytes fits only
  about a fifth of the time, so large frames wait windows, the buffer behind them fills, and bytes
  are thrown away. --fixed-window-counter models the fixed firmware (the count capped before it is
  narrowed).
- Framing (packet.c, MAVLink framing on, the default): packet_get_next and mavlink_frame as written:
  whole MAVLink 1 or 2 frames packed into an air packet while they fit (at most 250 data bytes); a
  frame whose payload is 226 bytes or more (mav_max_xmit less 25) is sent raw and split across packets;
  a frame not yet wholly in the buffer waits (and the radio yields) until it is, or until its serial
  time (its length x 10 ticks of 16 us) has passed, when what is there goes raw.
- RADIO_STATUS (mavlink.c's MAVLink_report, packet.c's check_response): when a radio packs a
  HEARTBEAT from its own host into an air packet it sends that host RADIO_STATUS from system 51 ('3'),
  component 68 ('D'), in the heartbeat's MAVLink version, if the 645-byte buffer has room (else at its
  next chance): rssi and noise (averaged as tdm.c does), the other radio's from its statistics packets,
  rxerrors (air packets lost here), fixed 0 (no ECC), txbuf = serial_read_space(): percent free of the
  1850-byte buffer in steps of 8 bytes. One report per heartbeat sent: that is the firmware's only rate
  limit.
- Loss: each air packet (data, yield or statistics) is lost whole with a probability from a
  Gilbert-Elliott channel per vehicle radio: good periods, exponentially distributed with mean
  --mean-good seconds (15 s: bad periods start at 1/15 a second), lose P_good; bad periods of fixed
  length B lose P_bad. Profiles: sik (P_good 1 %, P_bad 50 %, B 1 s: 4.1 % of packets lost on average),
  worse (3 %, 60 %, 2 s: 9.7 %), clear (no loss). The channel's periods come from one random
  generator seeded by --seed, the packet draws from another, so a run repeats up to its timing.

Not modelled: frequency hopping, its sync search and lost sync (the radios are always in step, on
one air timeline); ECC (golay), AES, RTS/CTS, duty cycle and listen-before-talk (all off by default); AT
commands; radio_transmit failures and packet_is_duplicate resends; PROTOCOL_VERSION replies
(check_response's seen_mavlink 3); the host UART's own buffer (the host's bytes queue without limit
before the 57600 line). Several vehicle radios (--vehicle-port more than once) take turns with the
ground radio (windows G, V1, V2, ...); the ground radio's packets reach every vehicle radio and theirs
only the ground radio, and no window is yielded to another radio: a plain SiK pair knows no
multipoint, so this is a sketch of multipoint firmware, not a model of it.

The log (--log), in lossy_relay.py's form (harness/relay_log_summary.py reads it): "drop" lines with
the direction ("up" ground station to vehicle, "down" vehicle to ground station), the messages hit and
the cause in brackets (buffer-full: the 1850-byte buffer; serial-full: the 645-byte one; air-loss: an
air packet lost); "hold" lines when the 8-bit counter keeps a frame back; "pass" lines for mission,
FTP and STATUSTEXT messages delivered whole, "cut" lines for those delivered with bytes missing (a bad
CRC); and every --stats-interval seconds one "stat" line per radio: bytes in from its host, sent over
the air, out to its host, and the buffers' fill:

  12.345 drop up MISSION_ITEM_INT seq=17 [buffer-full 37 bytes]
  12.351 pass down MISSION_REQUEST_INT seq=18
  12.400 hold down FILE_TRANSFER_PROTOCOL ... [window-counter: 263 bytes, budget 120]
  13.000 stat v1 in 5760 air 5811 out 1204 rx 1849/1849 tx 0/644

Commands with --control, one a line, each answered "ok ..." or "error ...":
  radio PROFILE         sik, worse or clear
  loss PGOOD [PBAD]     the loss in good (and bad) periods
  seed S                re-seed the channels
  gcs PORT              send the ground radio's output to 127.0.0.1:PORT (UDP ground side only)
  mark TEXT             write "mark TEXT" in the log
  inject HEX            put these bytes (a MAVLink frame) in the first vehicle radio's output to its
                        vehicle, as if they had come over the air
  outage S              lose every air packet for S seconds from now
  drop-first NAME       lose the next air packet to the ground radio that carries the message NAME
                        (e.g. AUTOPILOT_VERSION: the reply to a ground station's discovery lost)
  stats                 bytes and drops per direction since the last stats
  quit                  stop
"""

import argparse
import heapq
import os
import pty
import random
import selectors
import signal
import socket
import sys
import time
import tty

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from lossy_relay import FOLLOWED, NAMES, describe, frames  # noqa: E402

HOST = "127.0.0.1"
STX1, STX2 = 0xFE, 0xFD
US_PER_TICK = 16                    # timer2 ticks
RADIO_SYSTEM, RADIO_COMPONENT = ord("3"), ord("D")
MAX_PACKET_LENGTH = 252             # radio.h
TRAILER = 2                         # tdm.c's struct tdm_trailer
PREAMBLE_NIBBLES = 16               # radio_443x.c and radio_446x.c set settings.preamble_length
STATISTICS_BYTES = 4                # radio.h's struct statistics
LINK_UPDATE_US = 32768 * US_PER_TICK
RX_BUFF_MAX, TX_BUFF_MAX = 1850, 645

# (P_good, P_bad, bad period s, mean good period s)
PROFILES = {"sik": (0.01, 0.5, 1.0, 15.0), "worse": (0.03, 0.6, 2.0, 15.0), "clear": (0.0, 0.0, 1.0, 15.0)}


class Timing:
    """tdm_init's figures for an air rate in kbps, with or without ECC (golay), in 16 us ticks."""

    def __init__(self, air_rate=64, ecc=False, max_window_ms=131):
        self.ticks_per_byte = (8 + 8000000 // (air_rate * 1000)) // 16 + 1
        round_latency = (8 + 10 // 2) * self.ticks_per_byte + 13
        self.max_data = MAX_PACKET_LENGTH - TRAILER
        if ecc:     # golay doubles the bytes on air and adds four
            self.max_data = MAX_PACKET_LENGTH // 2 - (6 + TRAILER)
            self.ticks_per_byte *= 2
            round_latency += 4 * self.ticks_per_byte
        self.silence = 2 * round_latency
        window = 3 * (round_latency + self.max_data * self.ticks_per_byte)
        self.window = min(window, max_window_ms * (1000 // US_PER_TICK), 0x1FFF)
        # the flight estimates use the real preamble; the round timings above do not
        self.latency = round_latency + ((PREAMBLE_NIBBLES - 10) // 2) * self.ticks_per_byte
        self.mav_max_xmit = min((self.window - self.latency) // self.ticks_per_byte, self.max_data)

    def flight(self, length):
        """Air time of a packet of length bytes, trailer included: the firmware's own estimate
        (flight_time_estimate), which rounds the bytes up to 9 ticks (144 us) at 64 kbps where the air
        takes 125 us; the deployed firmware's measured losses (SiK pull request 97) follow it closer."""
        return self.latency + length * self.ticks_per_byte

    def max_xmit(self, remaining, fixed_counter):
        """tdm_serial_loop's byte budget with remaining ticks left, or None when it cannot send now."""
        if remaining < self.latency:
            return None
        count = (remaining - self.latency) // self.ticks_per_byte
        count = min(count, 255) if fixed_counter else count & 0xFF
        if count < TRAILER + 16:
            return None
        return min(count - (TRAILER + 1), self.max_data)

    def next_budget(self, remaining):
        """Ticks until the wrapped 8-bit count next reaches 255, or None if not in this window."""
        count = (remaining - self.latency) // self.ticks_per_byte
        wrap = count - count % 256 - 1
        if wrap < 0:
            return None
        return remaining - (self.latency + wrap * self.ticks_per_byte + self.ticks_per_byte - 1)


class Channel:
    """A Gilbert-Elliott channel: bad periods of fixed length start at exponential intervals."""

    def __init__(self, profile, seed):
        self.p_good, self.p_bad, self.bad_s, self.mean_good_s = profile
        self.periods = random.Random(seed)
        self.draws = random.Random(seed + 1000003)
        self.bad_from = self.bad_to = 0
        self.outage_until = 0
        self.plan(0)

    def plan(self, after_us):
        self.bad_from = after_us + int(self.periods.expovariate(1.0 / self.mean_good_s) * 1e6)
        self.bad_to = self.bad_from + int(self.bad_s * 1e6)

    def bad(self, t_us):
        while t_us >= self.bad_to:
            self.plan(self.bad_to)
        return t_us >= self.bad_from

    def lost(self, t_us):
        if t_us < self.outage_until:
            return True
        p = self.p_bad if self.bad(t_us) else self.p_good
        return p > 0 and self.draws.random() < p


class SerialLine:
    """A byte queue drained at a baud rate (8N1), evaluated lazily: settle(t) returns what has left."""

    def __init__(self, baud):
        self.baud = baud
        self.queue = bytearray()
        self.origin = 0       # when the byte at the head of the queue started
        self.sent = 0         # bytes sent since origin

    def push(self, data, t_us):
        if not self.queue:
            self.origin, self.sent = t_us, 0
        self.queue += data

    def settle(self, t_us):
        n = min(len(self.queue), (t_us - self.origin) * self.baud // 10000000 - self.sent)
        out = bytes(self.queue[:n])
        del self.queue[:n]
        self.sent += n
        return out

    def done_at(self, count):
        """When count more bytes of the queue will have left."""
        return self.origin + -(-(self.sent + count) * 10000000 // self.baud)


class Framer:
    """Cuts a serial byte stream into MAVLink frames (by their length byte, as a parser would)."""

    def __init__(self):
        self.buf = bytearray()

    def feed(self, data):
        self.buf += data
        out = []
        while self.buf:
            if self.buf[0] not in (STX1, STX2):
                i = next((k for k, c in enumerate(self.buf) if c in (STX1, STX2)), len(self.buf))
                out.append(bytes(self.buf[:i]))
                del self.buf[:i]
                continue
            n = self.length()
            if n is None or len(self.buf) < n:
                break
            out.append(bytes(self.buf[:n]))
            del self.buf[:n]
        return out

    def length(self):
        if len(self.buf) < 3:
            return None
        if self.buf[0] == STX1:
            return self.buf[1] + 8
        return self.buf[1] + 12 + (13 if self.buf[2] & 1 else 0)

    def need(self):
        """Bytes still to come before the frame being received is whole (at least 1)."""
        n = self.length()
        return max(1, (n if n is not None else 3) - len(self.buf))


class Packetizer:
    """packet.c with MAVLink framing: what a radio puts in its next air packet from its serial buffer."""

    def __init__(self, timing, serial_baud):
        self.mav_max_xmit = timing.mav_max_xmit
        # serial.c calls packet_set_serial_speed(SERIAL_SPEED * 125): ticks per byte, 10 at 57600
        self.serial_rate = 65536 // ((serial_baud // 1000) * 125) + 1
        self.pending = 0            # mav_pkt_len
        self.start = 0              # mav_pkt_start_time, in ticks
        self.max_time = 0           # mav_pkt_max_time
        self.heartbeat = 0          # seen_mavlink: 1 or 2 after a HEARTBEAT of that version went out
        self.held = None            # (frame length, budget) of a frame the budget kept back, for the log

    def next(self, rx, budget, tick):
        """Bytes taken from rx (a bytearray) for a packet of at most budget bytes; b'' for none."""
        self.held = None
        slen = min(len(rx), budget)
        if slen == 0:
            return b""
        if self.pending == 1:
            if slen == 1:
                if self.timed_out(tick):
                    self.pending = 0
                    return take(rx, 1)
                return b""
            self.pending = 0
        if self.pending:
            if slen < self.pending:
                if self.timed_out(tick):
                    self.pending = 0
                    return take(rx, slen)
                if len(rx) >= self.pending:
                    self.held = (self.pending, budget)
                return b""
            return self.frames(rx, budget)
        out = bytearray()
        i = 0
        while slen > 0:
            c = rx[i]
            if c in (STX1, STX2):
                if slen == 1:
                    if i == 0:
                        self.wait(1, tick)
                        return b""
                    break
                n = rx[i + 1]
                if n >= 255 - 25 or n + 25 > self.mav_max_xmit:
                    i += 1         # too big to frame: its STX goes raw, and the rest as it comes
                    slen -= 1
                    continue
                n += 8
                if c == STX2:
                    n += 4
                    if slen > 2 and rx[i + 2] & 1:
                        n += 13
                if i:
                    self.wait(n, tick)
                    return take(rx, i)
                if n > slen:
                    self.wait(n, tick)
                    if len(rx) >= n:
                        self.held = (n, budget)
                    return b""
                return self.frames(rx, budget)
            i += 1
            slen -= 1
        return take(rx, i)

    def wait(self, length, tick):
        self.pending = length
        self.start = tick
        self.max_time = (self.serial_rate if length == 1 else length * self.serial_rate) & 0xFFFF

    def timed_out(self, tick):
        return (tick - self.start) & 0xFFFF > self.max_time

    def frames(self, rx, budget):
        """mavlink_frame: whole frames from the head of rx while they fit in budget."""
        self.pending = 0
        used = 0
        while len(rx) - used >= 8:
            c = rx[used]
            if c not in (STX1, STX2):
                break
            extra = 8
            if c == STX2:
                extra += 4
                if rx[used + 2] & 1:
                    extra += 13
            n = rx[used + 1]
            if n >= 255 - extra or n + extra > budget - used:
                if used == 0 and n + extra <= len(rx):
                    self.held = (n + extra, budget)
                break
            if n + extra > len(rx) - used:
                break
            self.check_response(rx, used)
            used += n + extra
        return take(rx, used)

    def check_response(self, rx, i):
        if rx[i] == STX1 and rx[i + 1] == 9 and rx[i + 5] == 0:
            self.heartbeat = 1
        elif rx[i] == STX2 and rx[i + 1] <= 9 and rx[i + 7] == 0 and rx[i + 8] == 0 and rx[i + 9] == 0:
            self.heartbeat = 2


def take(buf, n):
    out = bytes(buf[:n])
    del buf[:n]
    return out


class RadioStatus:
    """RADIO_STATUS frames as mavlink.c sends them, built with pymavlink, from system 51 component 68."""

    def __init__(self):
        from pymavlink.dialects.v10 import common as v1
        from pymavlink.dialects.v20 import common as v2
        self.dialects = {1: v1, 2: v2}
        self.mav = {v: d.MAVLink(None, srcSystem=RADIO_SYSTEM, srcComponent=RADIO_COMPONENT) for v, d in self.dialects.items()}
        self.seq = 0

    def frame(self, version, rssi, remrssi, txbuf, noise, remnoise, rxerrors, fixed):
        mav = self.mav[version]
        mav.seq = self.seq
        self.seq = (self.seq + 1) & 0xFF
        msg = self.dialects[version].MAVLink_radio_status_message(rssi, remrssi, txbuf, noise, remnoise, rxerrors, fixed)
        return bytes(msg.pack(mav))

    @staticmethod
    def size(version):
        return 9 + (8 if version == 1 else 12)


class Radio:
    """One radio: its host's serial line in, the 1850-byte buffer to the air, the 645-byte one back."""

    def __init__(self, name, direction, timing, serial_baud, sched, log):
        self.name = name
        self.sched = sched
        self.direction = direction          # of the bytes it sends over the air: "up" or "down"
        self.timing = timing
        self.log = log
        self.line_in = SerialLine(serial_baud)
        self.rx = bytearray()               # serial to air
        self.line_out = SerialLine(serial_baud)   # air to serial: its queue is the 645-byte buffer
        self.packetizer = Packetizer(timing, serial_baud)
        self.status = RadioStatus()
        self.framer = Framer()
        self.to_host = None                 # callable(bytes, t_us): each frame (or run of other bytes) for the host
        self.wake = None                    # when the next frame to the host will be whole
        self.rssi = self.noise = 0          # statistics.average_rssi, average_noise
        self.remote = (0, 0)                # remote_statistics
        self.rx_errors = 0
        self.send_statistics = False
        self.counts = dict.fromkeys(("in", "air", "out", "buffer_full", "serial_full", "air_loss"), 0)
        self.labels = []                    # (offset in all bytes from the host, length, the write): to name drops
        self.in_offset = 0

    # ---- serial side
    def from_host(self, data, t_us):
        self.settle(t_us)
        self.line_in.push(data, t_us)
        self.labels.append((self.in_offset, len(data), data))
        self.in_offset += len(data)
        self.counts["in"] += len(data)

    def settle(self, t_us):
        """Brings the serial lines up to t_us: bytes in from the host, bytes out to it."""
        arrived = self.line_in.settle(t_us)
        if arrived:
            room = RX_BUFF_MAX - 1 - len(self.rx)
            self.rx += arrived[:room]
            if len(arrived) > room:
                self.dropped_in(len(arrived) - room, t_us)
            self.forget_labels()
        self.flush_out(t_us)
        self.report(t_us)
        self.arm_out()

    def forget_labels(self):
        done = self.in_offset - len(self.line_in.queue)
        while self.labels and self.labels[0][0] + self.labels[0][1] <= done:
            self.labels.pop(0)

    def dropped_in(self, n, t_us):
        self.counts["buffer_full"] += n
        done = self.in_offset - len(self.line_in.queue)
        what = []
        for start, length, data in self.labels:
            lo, hi = max(0, done - n - start), min(length, done - start)
            if lo < hi:
                what.append(cut_frames(data, lo, hi))
        self.log(t_us, "drop %s %s [buffer-full %d bytes]" % (self.direction, " | ".join(what), n))

    def flush_out(self, t_us):
        out = self.line_out.settle(t_us)
        if out and self.to_host:
            for frame in self.framer.feed(out):
                self.counts["out"] += len(frame)
                self.to_host(frame, t_us)

    def arm_out(self):
        """A timer for when the frame now going out to the host will be whole."""
        if not self.line_out.queue:
            return
        t = self.line_out.done_at(min(self.framer.need(), len(self.line_out.queue)))
        if t != self.wake:
            self.wake = t
            self.sched.at(t, self.settle_now)

    def settle_now(self):
        self.settle(self.sched.now)

    def from_air(self, data, t_us):
        """serial_write_buf: what fits in the 645-byte buffer, the rest thrown away."""
        self.settle(t_us)
        room = TX_BUFF_MAX - 1 - len(self.line_out.queue)
        if len(data) > room:
            self.counts["serial_full"] += len(data) - room
            self.log(t_us, "drop %s %s [serial-full %d/%d bytes]" % (
                other(self.direction), describe_packet(data[room:]), len(data) - room, len(data)))
        if room > 0:
            self.line_out.push(data[:room], t_us)
            self.arm_out()

    def report(self, t_us):
        """MAVLink_report: a RADIO_STATUS to the host once its heartbeat went over the air, if it fits."""
        version = self.packetizer.heartbeat
        if not version:
            return
        if TX_BUFF_MAX - 1 - len(self.line_out.queue) < RadioStatus.size(version):
            return
        self.packetizer.heartbeat = 0
        free = RX_BUFF_MAX - len(self.rx)
        txbuf = 100 * (free // 8) // (RX_BUFF_MAX // 8)
        frame = self.status.frame(version, self.rssi, self.remote[0], txbuf, self.noise, self.remote[1],
                                  self.rx_errors, 0)
        self.line_out.push(frame, t_us)
        self.arm_out()

    # ---- air side
    def packet(self, budget, unwrapped, t_us):
        """The data of the next air packet (packet_get_next), after bringing the serial side to t_us;
        a frame kept back that the unwrapped budget would have let through is logged as held."""
        self.settle(t_us)
        data = self.packetizer.next(self.rx, budget, t_us // US_PER_TICK)
        held = self.packetizer.held
        if held and held[0] <= unwrapped:
            self.log(t_us, "hold %s %s [window-counter: %d bytes, budget %d]" % (
                self.direction, describe_packet(bytes(self.rx[:held[0]])), held[0], held[1]))
        self.counts["air"] += len(data)
        if data:
            self.report(t_us)
        return data

    def heard(self, rssi):
        self.rssi = (rssi + 7 * self.rssi) // 8

    def sample_noise(self, noise):
        self.noise = (noise + 3 * self.noise) // 4


def other(direction):
    return "down" if direction == "up" else "up"


def intact(frame):
    """Whether a frame delivered to a host has its CRC right (bytes lost on the way make it wrong)."""
    from pymavlink.dialects.v20 import common
    from pymavlink.generator.mavcrc import x25crc
    header = 10 if frame[0] == STX2 else 6
    end = header + frame[1]
    if len(frame) < end + 2:
        return False
    msgid = frame[7] | frame[8] << 8 | frame[9] << 16 if frame[0] == STX2 else frame[5]
    known = common.mavlink_map.get(msgid)
    if known is None:
        return True
    crc = x25crc(frame[1:end])
    crc.accumulate([known.crc_extra])
    return crc.crc == frame[end] | frame[end + 1] << 8


def cut_frames(data, lo, hi):
    """The frames of one write from the host that lost bytes lo to hi (long writes only by size)."""
    if len(data) > 4096:
        return "%d bytes of a %d-byte write" % (hi - lo, len(data))
    cut, i = [], 0
    framer = Framer()
    for piece in framer.feed(data) + [bytes(framer.buf)]:
        if piece and i < hi and i + len(piece) > lo:
            cut.append(describe_packet(piece))
        i += len(piece)
    return " | ".join(cut)


def describe_packet(data):
    return " | ".join(describe(m, p) for m, p in frames(data)) or "%d raw bytes" % len(data)


class Scheduler:
    """A timer heap on simulated microseconds."""

    def __init__(self):
        self.heap = []
        self.now = 0
        self.count = 0

    def at(self, t_us, fn, *args):
        self.count += 1
        heapq.heappush(self.heap, (max(t_us, self.now), self.count, fn, args))

    def next_time(self):
        return self.heap[0][0] if self.heap else None

    def run_until(self, t_us):
        while self.heap and self.heap[0][0] <= t_us:
            t, _, fn, args = heapq.heappop(self.heap)
            self.now = t
            fn(*args)
        self.now = max(self.now, t_us)


class Air:
    """The TDM rounds of a ground radio and its vehicle radios on one simulated air timeline."""

    RSSI_GOOD, RSSI_BAD, NOISE = 180, 110, 40

    def __init__(self, ground, vehicles, timing, channels, scheduler, log, fixed_counter=False):
        self.ground = ground
        self.vehicles = vehicles
        self.order = [ground] + vehicles
        self.timing = timing
        self.channels = channels            # one per vehicle radio
        self.sched = scheduler
        self.log = log
        self.fixed_counter = fixed_counter
        self.owner = None
        self.window_end = 0                 # in ticks
        self.yielded = set()
        self.bonus = None
        self.turn = -1
        self.generation = 0                 # windows started: stale polls from an ended window are ignored
        self.packets = {"up": [0, 0], "down": [0, 0]}   # air packets sent, lost
        self.drop_first = set()             # message ids whose next air packet to the ground radio is lost
        self.sched.at(0, self.start_window)
        self.sched.at(LINK_UPDATE_US, self.link_update)

    def start_window(self):
        t = self.sched.now
        self.turn = (self.turn + 1) % len(self.order)
        self.owner = self.order[self.turn]
        self.yielded.clear()
        self.bonus = None
        self.generation += 1
        start = t // US_PER_TICK
        self.window_end = start + self.timing.window
        self.poll(self.owner, self.generation)
        self.sched.at((self.window_end + self.timing.silence) * US_PER_TICK, self.start_window)

    def link_update(self):
        for radio in self.order:
            radio.send_statistics = True
        self.sched.at(self.sched.now + LINK_UPDATE_US, self.link_update)

    def poll(self, radio, generation):
        """tdm_serial_loop's turn for radio at the scheduler's time: send, yield, or wait for budget."""
        if generation != self.generation or radio in self.yielded:
            return
        if radio is not self.owner and radio is not self.bonus:
            return
        t = self.sched.now
        tick = t // US_PER_TICK
        remaining = self.window_end - tick
        budget = self.timing.max_xmit(remaining, self.fixed_counter)
        if budget is None:
            wait = None if self.fixed_counter or remaining < self.timing.latency else self.timing.next_budget(remaining)
            if wait is not None and wait > 0:
                self.sched.at(t + wait * US_PER_TICK, self.poll, radio, generation)
            return
        if radio is self.owner:
            radio.sample_noise(self.NOISE)
        data = radio.packet(budget, self.timing.max_xmit(remaining, True) or 0, t)
        if data:
            self.transmit(radio, data, t, generation, "data")
        elif radio is self.owner and radio.send_statistics and budget >= STATISTICS_BYTES:
            radio.send_statistics = False
            self.transmit(radio, b"", t, generation, "statistics")
        else:
            self.yielded.add(radio)
            self.transmit(radio, b"", t, generation, "yield")

    def transmit(self, radio, data, t, generation, kind):
        length = len(data) + TRAILER + (STATISTICS_BYTES if kind == "statistics" else 0)
        arrival = t + self.timing.flight(length) * US_PER_TICK
        for receiver in self.receivers(radio):
            self.sched.at(arrival, self.receive, radio, receiver, data, kind, generation)
        if kind != "yield":
            self.sched.at(arrival, self.poll, radio, generation)

    def receivers(self, radio):
        return self.vehicles if radio is self.ground else [self.ground]

    def channel(self, a, b):
        vehicle = b if a is self.ground else a
        return self.channels[self.vehicles.index(vehicle)]

    def receive(self, sender, receiver, data, kind, generation):
        t = self.sched.now
        channel = self.channel(sender, receiver)
        counts = self.packets[sender.direction]
        counts[0] += 1
        lost, cause = channel.lost(t), "air-loss"
        first = self.drop_first.intersection(m for m, _ in frames(data)) if data and receiver is self.ground else None
        if first:
            self.drop_first -= first
            lost, cause = True, "drop-first"
        if lost:
            counts[1] += 1
            receiver.rx_errors = min(receiver.rx_errors + 1, 0xFFFF)
            receiver.counts["air_loss"] += len(data)
            if data:
                self.log(t, "drop %s %s [%s %d bytes]" % (sender.direction, describe_packet(data), cause, len(data)))
            return
        receiver.heard(self.RSSI_BAD if channel.bad(t) else self.RSSI_GOOD)
        if kind == "statistics":
            receiver.remote = (sender.rssi, sender.noise)
        elif data:
            receiver.from_air(data, t)
        elif kind == "yield" and sender is self.owner and len(self.order) == 2 and generation == self.generation:
            self.bonus = receiver
            self.poll(receiver, generation)


class Relay:
    """The sockets (and pty) around an Air: real time in, simulated time out, on one selector."""

    def __init__(self, args, profile, log):
        self.start = time.monotonic()
        self.logfile = log
        self.sched = Scheduler()
        self.timing = Timing(args.air_rate, args.ecc)
        self.sel = selectors.DefaultSelector()
        self.ground = Radio("g", "up", self.timing, args.serial_baud, self.sched, self.write)
        self.vehicles = [Radio("v%d" % (i + 1), "down", self.timing, args.serial_baud, self.sched, self.write)
                         for i in range(len(args.vehicle_port))]
        self.channels = [Channel(profile, args.seed * 7919 + i) for i in range(len(self.vehicles))]
        self.air = Air(self.ground, self.vehicles, self.timing, self.channels, self.sched, self.write,
                       args.fixed_window_counter)
        self.stats_interval_us = int(args.stats_interval * 1e6)
        self.sched.at(self.stats_interval_us, self.periodic_stats)
        self.vehicle_socks, self.vehicle_addrs = [], []
        for i, port in enumerate(args.vehicle_port):
            s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
            s.bind((HOST, port))
            s.setblocking(False)
            self.sel.register(s, selectors.EVENT_READ, ("vehicle", i))
            self.vehicle_socks.append(s)
            self.vehicle_addrs.append(None)
            self.vehicles[i].to_host = self.sender(i)
        self.gcs_sock = self.pty_master = None
        self.ignored = 0
        if args.gcs_pty:
            self.pty_master, self.pty_slave = pty.openpty()
            tty.setraw(self.pty_slave)
            os.set_blocking(self.pty_master, False)
            if os.path.lexists(args.gcs_pty):
                os.unlink(args.gcs_pty)
            os.symlink(os.ttyname(self.pty_slave), args.gcs_pty)
            self.sel.register(self.pty_master, selectors.EVENT_READ, ("pty", 0))
            self.ground.to_host = self.to_pty
        else:
            self.gcs_sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
            self.gcs_sock.bind((HOST, args.relay_port))
            self.gcs_sock.setblocking(False)
            self.gcs_addr = (HOST, args.gcs_port)
            self.sel.register(self.gcs_sock, selectors.EVENT_READ, ("gcs", 0))
            self.ground.to_host = self.to_gcs
        self.last = {"up": [0, 0], "down": [0, 0]}

    def now_us(self):
        return int((time.monotonic() - self.start) * 1e6)

    def write(self, t_us, line):
        if self.logfile:
            self.logfile.write("%.3f %s\n" % (t_us / 1e6, line))

    def follow(self, direction, frame, t_us):
        msgs = list(frames(frame))
        if any(m in FOLLOWED for m, _ in msgs):
            fate = "pass" if intact(frame) else "cut"
            self.write(t_us, "%s %s %s" % (fate, direction, " | ".join(describe(m, p) for m, p in msgs)))

    def sender(self, i):
        def send(frame, t_us):
            self.follow("up", frame, t_us)
            if self.vehicle_addrs[i] is None:
                self.write(t_us, "unsent up no vehicle has sent to %d yet" % self.vehicle_socks[i].getsockname()[1])
                return
            try:
                self.vehicle_socks[i].sendto(frame, self.vehicle_addrs[i])
            except OSError as e:
                self.write(t_us, "unsent up %s" % e)
        return send

    def to_gcs(self, frame, t_us):
        self.follow("down", frame, t_us)
        try:
            self.gcs_sock.sendto(frame, self.gcs_addr)
        except OSError as e:    # nobody listening yet: as a radio would, lose it
            self.write(t_us, "unsent down %s" % e)

    def to_pty(self, frame, t_us):
        self.follow("down", frame, t_us)
        try:
            os.write(self.pty_master, frame)
        except BlockingIOError:
            self.write(t_us, "drop down %s [pty-full %d bytes]" % (describe_packet(frame), len(frame)))

    def periodic_stats(self):
        t = self.sched.now
        for radio in [self.ground] + self.vehicles:
            radio.settle(t)
            c = radio.counts
            self.write(t, "stat %s in %d air %d out %d rx %d/%d tx %d/%d" % (
                radio.name, c["in"], c["air"], c["out"], len(radio.rx), RX_BUFF_MAX - 1,
                len(radio.line_out.queue), TX_BUFF_MAX - 1))
        if self.logfile:
            self.logfile.flush()
        self.sched.at(t + self.stats_interval_us, self.periodic_stats)

    def command(self, line):
        words = line.split()
        if not words:
            return "ok"
        cmd, args = words[0], words[1:]
        t = self.sched.now
        if cmd == "radio" and len(args) == 1:
            if args[0] not in PROFILES:
                return "error unknown profile %s: %s" % (args[0], " ".join(PROFILES))
            for ch in self.channels:
                ch.p_good, ch.p_bad, ch.bad_s, ch.mean_good_s = PROFILES[args[0]]
            self.write(t, "mark radio %s" % args[0])
            return "ok radio %s" % args[0]
        if cmd == "loss" and len(args) in (1, 2):
            good = float(args[0])
            bad = float(args[1]) if len(args) == 2 else self.channels[0].p_bad
            if not (0 <= good <= 1 and 0 <= bad <= 1):
                return "error loss must be in [0, 1]"
            for ch in self.channels:
                ch.p_good, ch.p_bad = good, bad
            self.write(t, "mark loss good %.3f bad %.3f" % (good, bad))
            return "ok loss %s %s" % (good, bad)
        if cmd == "seed" and len(args) == 1:
            profile = (self.channels[0].p_good, self.channels[0].p_bad, self.channels[0].bad_s, self.channels[0].mean_good_s)
            for i, ch in enumerate(self.channels):
                fresh = Channel(profile, int(args[0]) * 7919 + i)
                fresh.plan(t)
                self.channels[i] = fresh
            self.air.channels = self.channels
            self.write(t, "mark seed %d" % int(args[0]))
            return "ok seed %d" % int(args[0])
        if cmd == "gcs" and len(args) == 1:
            if self.gcs_sock is None:
                return "error the ground side is a pty"
            self.gcs_addr = (HOST, int(args[0]))
            self.write(t, "mark gcs %d" % int(args[0]))
            return "ok gcs %d" % int(args[0])
        if cmd == "mark":
            self.write(t, "mark " + " ".join(args))
            return "ok"
        if cmd == "inject" and len(args) == 1:
            if self.vehicle_addrs[0] is None:
                return "error no vehicle yet"
            data = bytes.fromhex(args[0])
            self.write(t, "inject up %s" % describe_packet(data))
            self.vehicles[0].from_air(data, t)
            return "ok inject"
        if cmd == "outage" and len(args) == 1:
            for ch in self.channels:
                ch.outage_until = t + int(float(args[0]) * 1e6)
            self.write(t, "mark outage %g s" % float(args[0]))
            return "ok outage %g" % float(args[0])
        if cmd == "drop-first" and len(args) == 1:
            ids = [i for i, name in NAMES.items() if name == args[0].upper()]
            if not ids:
                return "error unknown message %s (known: %s)" % (args[0], ", ".join(sorted(set(NAMES.values()))))
            self.air.drop_first.update(ids)
            self.write(t, "mark drop-first %s" % args[0].upper())
            return "ok drop-first %s" % args[0].upper()
        if cmd == "stats":
            now = {d: list(self.air.packets[d]) for d in ("up", "down")}
            answer = "ok up %d %d down %d %d ignored %d" % (
                now["up"][0] - self.last["up"][0], now["up"][1] - self.last["up"][1],
                now["down"][0] - self.last["down"][0], now["down"][1] - self.last["down"][1], self.ignored)
            self.last, self.ignored = now, 0
            self.write(t, "mark stats " + answer[3:])
            return answer
        return "error unknown command: " + line.strip()

    def run(self, control):
        if control:
            self.sel.register(sys.stdin.fileno(), selectors.EVENT_READ, ("control", 0))
        pending = b""
        while True:
            self.sched.run_until(self.now_us())
            nxt = self.sched.next_time()
            timeout = None if nxt is None else max(0.0, (nxt - self.now_us()) / 1e6)
            for key, _ in self.sel.select(timeout):
                kind, i = key.data
                self.sched.run_until(self.now_us())
                t = self.sched.now
                if kind == "vehicle":
                    try:
                        data, addr = self.vehicle_socks[i].recvfrom(65536)
                    except OSError:      # an ICMP port unreachable for an earlier send: no datagram
                        continue
                    if addr[0] == HOST:
                        self.vehicle_addrs[i] = addr
                        self.vehicles[i].from_host(data, t)
                elif kind == "gcs":
                    try:
                        data, addr = self.gcs_sock.recvfrom(65536)
                    except OSError:
                        continue
                    if addr != self.gcs_addr:
                        self.ignored += 1
                        continue
                    self.ground.from_host(data, t)
                elif kind == "pty":
                    try:
                        data = os.read(self.pty_master, 65536)
                    except OSError:
                        continue
                    self.ground.from_host(data, t)
                else:
                    chunk = os.read(sys.stdin.fileno(), 65536)
                    pending += chunk
                    while b"\n" in pending or not chunk:
                        line, _, pending = pending.partition(b"\n")
                        line = line.decode()
                        if line.strip() == "quit" or (not chunk and not line.strip()):
                            return
                        print(self.command(line), flush=True)
                    if self.logfile:
                        self.logfile.flush()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--vehicle-port", type=int, action="append", required=True,
                    help="where a vehicle sends (SITL's udpclient port); more than once for several vehicle radios")
    ap.add_argument("--gcs-port", type=int, help="where the ground station listens (UDP ground side)")
    ap.add_argument("--relay-port", type=int, default=0, help="the ground radio's own port towards the ground station")
    ap.add_argument("--gcs-pty", help="instead of UDP: a pseudo-terminal for the ground station, linked here")
    ap.add_argument("--profile", choices=sorted(PROFILES), default="sik", help="the air's loss (default sik)")
    ap.add_argument("--loss-good", type=float, help="loss probability of an air packet in good periods")
    ap.add_argument("--loss-bad", type=float, help="loss probability of an air packet in bad periods")
    ap.add_argument("--bad-seconds", type=float, help="length of a bad period")
    ap.add_argument("--mean-good", type=float, help="mean length of a good period, in seconds")
    ap.add_argument("--air-rate", type=int, default=64, help="air data rate in kbps (AIR_SPEED, default 64)")
    ap.add_argument("--ecc", action="store_true", help="golay error correction on (ECC 1; off by default)")
    ap.add_argument("--serial-baud", type=int, default=57600, help="host <-> radio baud (SERIAL_SPEED, default 57600)")
    ap.add_argument("--fixed-window-counter", action="store_true", help="model SiK with pull request 97's fix")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--log", help="the log of drops, holds, transfer messages and buffer fill")
    ap.add_argument("--stats-interval", type=float, default=1.0, help="seconds between stat lines in the log")
    ap.add_argument("--control", action="store_true", help="read commands on stdin")
    a = ap.parse_args()
    if (a.gcs_port is None) == (a.gcs_pty is None):
        ap.error("give either --gcs-port or --gcs-pty")
    given = (a.loss_good, a.loss_bad, a.bad_seconds, a.mean_good)
    profile = tuple(d if g is None else g for g, d in zip(given, PROFILES[a.profile]))
    log = open(a.log, "a", buffering=1 << 16) if a.log else None
    relay = Relay(a, profile, log)
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(0))   # stop as on quit: the log flushed, the pty link removed
    if a.gcs_pty:
        print("ready vehicle %s pty %s" % (",".join(map(str, a.vehicle_port)), a.gcs_pty), flush=True)
    else:
        print("ready vehicle %s relay %d gcs %d" % (",".join(map(str, a.vehicle_port)),
                                                    relay.gcs_sock.getsockname()[1], a.gcs_port), flush=True)
    try:
        relay.run(a.control)
    except KeyboardInterrupt:
        pass
    finally:
        if log:
            log.close()
        if a.gcs_pty and os.path.islink(a.gcs_pty):
            os.unlink(a.gcs_pty)


if __name__ == "__main__":
    os.environ.setdefault("PYTHONUNBUFFERED", "1")
    main()
