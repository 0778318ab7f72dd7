package dolphin.bench;

import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.common.msg_mission_item_int;
import com.MAVLink.common.msg_sys_status;
import com.MAVLink.minimal.msg_heartbeat;
import com.MAVLink.standard.msg_global_position_int;
import dolphin.mavlink.codec.FrameWriter;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.SplittableRandom;

/**
 * The benchmark's input: a deterministic mixed stream of MAVLink 2 frames written by
 * {@link FrameWriter}, as a vehicle link carries them. Three vehicles (system ids 1 to 3,
 * component 1), each with its own writer and sequence numbers, send HEARTBEAT, SYS_STATUS,
 * GLOBAL_POSITION_INT and MISSION_ITEM_INT (a mission download) in equal shares, in a seeded random
 * order, with plausible, changing field values (a random walk around a home position, battery
 * draining, time advancing), so the payloads vary in length as MAVLink 2 truncation makes them.
 *
 * <p>{@code main(file, frames)} writes the stream to a file for pymavlink's side
 * (bench/pymavlink_parse.py) and prints its size and SHA-256; the JMH benchmarks read that file.
 */
public final class MixedStream {

    public static final long SEED = 0x5EED_2026L;

    /** Message names in the order of {@link #MSGIDS}. */
    public static final String[] NAMES = {"HEARTBEAT", "SYS_STATUS", "GLOBAL_POSITION_INT", "MISSION_ITEM_INT"};
    public static final int[] MSGIDS = {0, 1, 33, 73};

    private MixedStream() {
    }

    /** The messages of the stream, in order (sender in {@code sysid}), before framing. */
    public static List<MAVLinkMessage> messages(int count, long seed) {
        SplittableRandom rnd = new SplittableRandom(seed);
        Vehicle[] vehicles = {new Vehicle(1, rnd), new Vehicle(2, rnd), new Vehicle(3, rnd)};
        List<MAVLinkMessage> out = new ArrayList<>(count);
        for (int i = 0; i < count; i++) {
            Vehicle v = vehicles[rnd.nextInt(vehicles.length)];
            v.advance(rnd);
            MAVLinkMessage m = switch (rnd.nextInt(4)) {
                case 0 -> v.heartbeat();
                case 1 -> v.sysStatus(rnd);
                case 2 -> v.globalPosition();
                default -> v.missionItem(rnd);
            };
            m.sysid = v.sysid;
            m.compid = 1;
            out.add(m);
        }
        return out;
    }

    /** The frames of the stream, each written by its sender's {@link FrameWriter}. */
    public static List<byte[]> frames(int count, long seed) {
        FrameWriter[] writers = {new FrameWriter(1, 1), new FrameWriter(2, 1), new FrameWriter(3, 1)};
        List<byte[]> frames = new ArrayList<>(count);
        for (MAVLinkMessage m : messages(count, seed)) {
            frames.add(writers[m.sysid - 1].write(m));
        }
        return frames;
    }

    public static byte[] concat(List<byte[]> frames) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (byte[] f : frames) {
            out.writeBytes(f);
        }
        return out.toByteArray();
    }

    /**
     * Splits a stream of unsigned MAVLink 2 frames at frame boundaries (offsets, plus the end), checking
     * that it is one: a start byte at every boundary, no signed frame, the last frame ending at the end.
     */
    public static int[] boundaries(byte[] stream) {
        List<Integer> offsets = new ArrayList<>();
        int p = 0;
        while (p < stream.length) {
            if ((stream[p] & 0xFF) != 0xFD || (stream[p + 2] & 0x01) != 0) {
                throw new IllegalArgumentException("not an unsigned MAVLink 2 frame at byte " + p);
            }
            offsets.add(p);
            p += 12 + (stream[p + 1] & 0xFF);
        }
        if (p != stream.length) {
            throw new IllegalArgumentException("the last frame runs past the end of the stream");
        }
        offsets.add(p);
        return offsets.stream().mapToInt(Integer::intValue).toArray();
    }

    public static String sha256(byte[] bytes) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }

    /** {@code MixedStream FILE FRAMES}: writes the stream and prints frames, bytes, mix and SHA-256. */
    public static void main(String[] args) throws IOException {
        if (args.length != 2) {
            System.err.println("usage: MixedStream FILE FRAMES");
            System.exit(2);
        }
        Path file = Path.of(args[0]);
        int count = Integer.parseInt(args[1]);
        List<byte[]> frames = frames(count, SEED);
        byte[] stream = concat(frames);
        Files.write(file, stream);
        int[] perType = new int[NAMES.length];
        for (byte[] f : frames) {
            int msgid = (f[7] & 0xFF) | (f[8] & 0xFF) << 8 | (f[9] & 0xFF) << 16;
            for (int t = 0; t < MSGIDS.length; t++) {
                if (MSGIDS[t] == msgid) {
                    perType[t]++;
                }
            }
        }
        StringBuilder mix = new StringBuilder();
        for (int t = 0; t < NAMES.length; t++) {
            mix.append(t == 0 ? "" : " ").append(NAMES[t]).append('=').append(perType[t]);
        }
        System.out.printf("stream %s: %d frames, %d bytes (%.1f bytes/frame), %s, sha256 %s%n", file, count, stream.length,
                (double) stream.length / count, mix, sha256(stream));
    }

    /** One simulated vehicle's state, advanced a little before each message it sends. */
    private static final class Vehicle {
        final int sysid;
        long timeBootMs;
        double lat;
        double lon;
        double relAlt;
        double heading;
        double voltage = 12_600;
        double remaining = 100;
        int missionSeq;
        final double homeLat;
        final double homeLon;

        Vehicle(int sysid, SplittableRandom rnd) {
            this.sysid = sysid;
            homeLat = 43.5605 + rnd.nextDouble(-0.01, 0.01);
            homeLon = 1.4807 + rnd.nextDouble(-0.01, 0.01);
            lat = homeLat;
            lon = homeLon;
            relAlt = 30;
            timeBootMs = 60_000 + rnd.nextInt(10_000);
        }

        void advance(SplittableRandom rnd) {
            timeBootMs += 20 + rnd.nextInt(80);
            heading = (heading + rnd.nextDouble(-5, 5) + 360) % 360;
            lat += rnd.nextDouble(-2e-6, 2e-6);
            lon += rnd.nextDouble(-2e-6, 2e-6);
            relAlt = Math.max(0, relAlt + rnd.nextDouble(-0.2, 0.2));
            voltage = Math.max(10_500, voltage - rnd.nextDouble(0, 0.5));
            remaining = Math.max(0, remaining - rnd.nextDouble(0, 0.005));
        }

        msg_heartbeat heartbeat() {
            msg_heartbeat m = new msg_heartbeat();
            m.custom_mode = 4;          // GUIDED
            m.type = 2;                 // MAV_TYPE_QUADROTOR
            m.autopilot = 3;            // MAV_AUTOPILOT_ARDUPILOTMEGA
            m.base_mode = 0x89 | 0x40;  // armed, custom mode, guided
            m.system_status = 4;        // MAV_STATE_ACTIVE
            m.mavlink_version = 3;
            return m;
        }

        msg_sys_status sysStatus(SplittableRandom rnd) {
            msg_sys_status m = new msg_sys_status();
            m.onboard_control_sensors_present = 0x1361FC2FL;
            m.onboard_control_sensors_enabled = 0x1321FC2FL;
            m.onboard_control_sensors_health = 0x1361FC2FL;
            m.load = 150 + rnd.nextInt(250);
            m.voltage_battery = (int) voltage;
            m.current_battery = (short) (800 + rnd.nextInt(1500));
            m.drop_rate_comm = 0;
            m.errors_comm = 0;
            m.battery_remaining = (byte) Math.round(remaining);
            return m;
        }

        msg_global_position_int globalPosition() {
            msg_global_position_int m = new msg_global_position_int();
            m.time_boot_ms = timeBootMs;
            m.lat = (int) Math.round(lat * 1e7);
            m.lon = (int) Math.round(lon * 1e7);
            m.relative_alt = (int) Math.round(relAlt * 1000);
            m.alt = m.relative_alt + 146_000;
            double speed = 500; // cm/s
            m.vx = (short) Math.round(speed * Math.cos(Math.toRadians(heading)));
            m.vy = (short) Math.round(speed * Math.sin(Math.toRadians(heading)));
            m.vz = (short) Math.round(-10 + 20 * Math.sin(timeBootMs / 1000.0));
            m.hdg = (int) Math.round(heading * 100) % 36000;
            return m;
        }

        msg_mission_item_int missionItem(SplittableRandom rnd) {
            msg_mission_item_int m = new msg_mission_item_int();
            m.target_system = 255;
            m.target_component = 190;
            m.seq = missionSeq;
            missionSeq = (missionSeq + 1) % 200;
            m.frame = 3;                // MAV_FRAME_GLOBAL_RELATIVE_ALT
            m.command = 16;             // MAV_CMD_NAV_WAYPOINT
            m.current = 0;
            m.autocontinue = 1;
            m.param1 = 0;               // hold time
            m.param2 = 2;               // acceptance radius, m
            m.param3 = 0;
            m.param4 = 0;
            m.x = (int) Math.round((homeLat + rnd.nextDouble(-0.002, 0.002)) * 1e7);
            m.y = (int) Math.round((homeLon + rnd.nextDouble(-0.002, 0.002)) * 1e7);
            m.z = (float) (20 + rnd.nextInt(40));
            m.mission_type = 0;
            return m;
        }
    }
}
