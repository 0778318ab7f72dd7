package dolphin.sim;

import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.common.msg_battery_status;
import com.MAVLink.common.msg_command_ack;
import com.MAVLink.common.msg_command_long;
import com.MAVLink.common.msg_extended_sys_state;
import com.MAVLink.common.msg_home_position;
import com.MAVLink.common.msg_mission_ack;
import com.MAVLink.common.msg_mission_clear_all;
import com.MAVLink.common.msg_mission_count;
import com.MAVLink.common.msg_mission_current;
import com.MAVLink.common.msg_mission_item;
import com.MAVLink.common.msg_mission_item_int;
import com.MAVLink.common.msg_mission_request;
import com.MAVLink.common.msg_mission_request_int;
import com.MAVLink.common.msg_mission_request_list;
import com.MAVLink.common.msg_mission_set_current;
import com.MAVLink.common.msg_request_data_stream;
import com.MAVLink.common.msg_set_mode;
import com.MAVLink.common.msg_statustext;
import com.MAVLink.common.msg_sys_status;
import com.MAVLink.enums.MAV_AUTOPILOT;
import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_DATA_STREAM;
import com.MAVLink.enums.MAV_LANDED_STATE;
import com.MAVLink.enums.MAV_MODE_FLAG;
import com.MAVLink.enums.MAV_RESULT;
import com.MAVLink.enums.MAV_SEVERITY;
import com.MAVLink.enums.MAV_STATE;
import com.MAVLink.enums.MAV_SYS_STATUS_SENSOR;
import com.MAVLink.minimal.msg_heartbeat;
import com.MAVLink.standard.msg_global_position_int;
import dolphin.core.Position;
import dolphin.mavlink.mission.MissionItem;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Consumer;

/**
 * One simulated ArduPilot vehicle: the identity, link and command behaviour of ArduCopter or
 * ArduPlane as ardupilot-behaviour.md records it. Driven by its {@link SimFleet}'s one thread; the
 * public methods are synchronized, so tests may read and change it from other threads.
 */
public final class SimVehicle {

    private static final Set<Integer> STREAMABLE = Set.of(msg_sys_status.MAVLINK_MSG_ID_SYS_STATUS,
            msg_global_position_int.MAVLINK_MSG_ID_GLOBAL_POSITION_INT, msg_mission_current.MAVLINK_MSG_ID_MISSION_CURRENT,
            msg_battery_status.MAVLINK_MSG_ID_BATTERY_STATUS, msg_home_position.MAVLINK_MSG_ID_HOME_POSITION,
            msg_extended_sys_state.MAVLINK_MSG_ID_EXTENDED_SYS_STATE);
    private static final long SECOND = 1_000_000_000L;
    private static final int FORCE_DISARM = 21196;

    private final int sysid;
    private final VehicleKind kind;
    private final SimOptions options;
    private final long bootNanos;
    private final Map<Integer, Long> intervals = new HashMap<>();
    private final Map<Integer, Long> nextDue = new HashMap<>();
    private Consumer<MAVLinkMessage> out = m -> { };
    private long nextHeartbeat;
    private long lastTick;
    private int mode;
    private boolean armed;
    private boolean silent;
    private double battery = 100;
    private Position position;
    private Position home;
    private Position target;
    private double speed;
    private int commandsHandled;
    private final MissionStore missionStore;
    private final MissionTransfer transfer;
    private final MissionFlight flight;

    SimVehicle(int sysid, VehicleKind kind, Position home, SimOptions options, long now) {
        this.sysid = sysid;
        this.kind = kind;
        this.options = options;
        this.bootNanos = now;
        this.home = home;
        this.position = home;
        this.mode = kind.bootMode;
        this.nextHeartbeat = now;
        this.lastTick = now;
        this.missionStore = new MissionStore(() -> this.home, options.missionCapacity());
        this.transfer = new MissionTransfer(missionStore, new TransferHost());
        this.flight = new MissionFlight(kind, missionStore, new FlightBody());
        if (kind.defaultStreamHz > 0) {
            for (int id : STREAMABLE) {
                intervals.put(id, (long) (SECOND / kind.defaultStreamHz));
            }
        }
    }

    void connect(Consumer<MAVLinkMessage> out) {
        this.out = out;
    }

    public int sysid() {
        return sysid;
    }

    public VehicleKind kind() {
        return kind;
    }

    public synchronized int mode() {
        return mode;
    }

    public synchronized String modeName() {
        return kind.family.modeName(mode);
    }

    public synchronized boolean armed() {
        return armed;
    }

    public synchronized double battery() {
        return battery;
    }

    public synchronized void setBattery(double percent) {
        battery = Math.max(0, Math.min(100, percent));
    }

    public synchronized Position position() {
        return position;
    }

    public synchronized Position home() {
        return home;
    }

    /** Messages the vehicle streams, with their intervals in clock nanoseconds. */
    public synchronized Map<Integer, Long> streams() {
        return Map.copyOf(intervals);
    }

    public synchronized int commandsHandled() {
        return commandsHandled;
    }

    /** A silent vehicle sends nothing and ignores what it hears, as if switched off or out of range. */
    public synchronized void setSilent(boolean value) {
        silent = value;
    }

    /** Forgets every requested stream, as a reboot does; the ground station must ask again. */
    public synchronized void resetStreams() {
        intervals.clear();
        nextDue.clear();
    }

    /** The stored mission, home first (seq 0 is always the vehicle's home, as in ArduPilot). */
    public synchronized List<MissionItem> mission() {
        return missionStore.items();
    }

    /** Camera items (IMAGE_START/STOP_CAPTURE, DO_DIGICAM_CONTROL, DO_SET_CAM_TRIGG_DIST) the missions ran. */
    public synchronized int cameraCommands() {
        return flight.cameraCommands();
    }

    /** The current mission item (seq), as MISSION_CURRENT reports it while the mission runs. */
    public synchronized int missionCurrent() {
        return flight.current();
    }

    /** MISSION_STATE: NO_MISSION, NOT_STARTED, ACTIVE, PAUSED or COMPLETE. */
    public synchronized int missionState() {
        return flight.state();
    }

    /** Whether an upload is in progress. */
    public synchronized boolean missionUploading() {
        return transfer.uploading();
    }

    /** Moves towards {@code to} at {@code metresPerSecond} (straight line, heights included). */
    public synchronized void flyTo(Position to, double metresPerSecond) {
        target = to;
        speed = metresPerSecond;
    }

    /** Mode changes by "someone else", e.g. a pilot's switch: the ground station is not asked. */
    public synchronized void setMode(int customMode) {
        int from = mode;
        mode = customMode;
        flight.modeChanged(from, mode);
    }

    synchronized void tick(long now) {
        double dt = (now - lastTick) / 1e9;
        lastTick = now;
        if (armed) {
            battery = Math.max(0, battery - options.drainPercentPerMinute() * dt / 60);
        }
        move(dt);
        transfer.tick(now);
        flight.tick(dt);
        if (silent) {
            return;
        }
        if (now >= nextHeartbeat) {
            out.accept(heartbeat());
            nextHeartbeat = now + SECOND;
        }
        for (Map.Entry<Integer, Long> e : intervals.entrySet()) {
            long due = nextDue.getOrDefault(e.getKey(), now);
            if (now >= due) {
                out.accept(telemetry(e.getKey()));
                nextDue.put(e.getKey(), Math.max(due + e.getValue(), now));
            }
        }
    }

    private void move(double dt) {
        if (target == null || speed <= 0 || dt <= 0) {
            return;
        }
        double[] ned = position.displacementTo(target);
        double dist = Math.sqrt(ned[0] * ned[0] + ned[1] * ned[1] + ned[2] * ned[2]);
        double step = speed * dt;
        if (dist <= step) {
            position = target;
            target = null;
        } else {
            double f = step / dist;
            position = position.displace(ned[0] * f, ned[1] * f, ned[2] * f);
        }
    }

    synchronized void handle(MAVLinkMessage m, long now) {
        if (silent) {
            return;
        }
        if (m instanceof msg_command_long c && c.target_system == sysid) {
            commandsHandled++;
            ack(c, command(c, now));
        } else if (m instanceof msg_set_mode s && s.target_system == sysid) {
            setModeIfValid(s.custom_mode);
        } else if (m instanceof msg_request_data_stream r && r.target_system == sysid) {
            requestDataStream(r);
        } else if (missionTarget(m) == sysid) {
            transfer.handle(m, now);
        } else if (m instanceof msg_mission_set_current s && s.target_system == sysid) {
            flight.setCurrent(s.seq);
        }
    }

    private int command(msg_command_long c, long now) {
        return switch (c.command) {
            case MAV_CMD.MAV_CMD_COMPONENT_ARM_DISARM -> c.param1 == 1 ? arm(now) : disarm(c.param2);
            case MAV_CMD.MAV_CMD_DO_SET_MODE -> ((int) c.param1 & MAV_MODE_FLAG.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED) != 0
                    && setModeIfValid((long) c.param2) ? MAV_RESULT.MAV_RESULT_ACCEPTED : MAV_RESULT.MAV_RESULT_FAILED;
            case MAV_CMD.MAV_CMD_DO_SET_HOME -> setHome(c);
            case MAV_CMD.MAV_CMD_BATTERY_RESET -> {
                // param1 is a mask of battery instances; this vehicle has instance 0 only
                if (((int) c.param1 & 1) == 0) {
                    yield MAV_RESULT.MAV_RESULT_FAILED;
                }
                battery = Math.max(0, Math.min(100, c.param2));
                yield MAV_RESULT.MAV_RESULT_ACCEPTED;
            }
            case MAV_CMD.MAV_CMD_SET_MESSAGE_INTERVAL -> setInterval((int) c.param1, c.param2);
            case MAV_CMD.MAV_CMD_REQUEST_MESSAGE -> {
                if (!STREAMABLE.contains((int) c.param1)) {
                    yield MAV_RESULT.MAV_RESULT_FAILED;
                }
                out.accept(telemetry((int) c.param1));
                yield MAV_RESULT.MAV_RESULT_ACCEPTED;
            }
            case MAV_CMD.MAV_CMD_GET_HOME_POSITION -> {
                out.accept(telemetry(msg_home_position.MAVLINK_MSG_ID_HOME_POSITION));
                yield MAV_RESULT.MAV_RESULT_ACCEPTED;
            }
            case MAV_CMD.MAV_CMD_MISSION_START -> missionStart(c);
            case MAV_CMD.MAV_CMD_DO_SET_MISSION_CURRENT -> flight.setCurrent((int) c.param1) ? MAV_RESULT.MAV_RESULT_ACCEPTED
                    : MAV_RESULT.MAV_RESULT_FAILED;
            case MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH -> setModeIfValid(kind.rtlMode) ? MAV_RESULT.MAV_RESULT_ACCEPTED
                    : MAV_RESULT.MAV_RESULT_FAILED;
            case MAV_CMD.MAV_CMD_NAV_LAND -> kind == VehicleKind.COPTER && setModeIfValid(MissionFlight.COPTER_LAND_MODE)
                    ? MAV_RESULT.MAV_RESULT_ACCEPTED : MAV_RESULT.MAV_RESULT_UNSUPPORTED;
            default -> MAV_RESULT.MAV_RESULT_UNSUPPORTED;
        };
    }

    /** GCS_MAVLINK_Copter::handle_MAV_CMD_MISSION_START: p1 = p2 = 0, switch to AUTO, auto_armed. */
    private int missionStart(msg_command_long c) {
        if (c.param1 != 0 || c.param2 != 0) {
            return MAV_RESULT.MAV_RESULT_DENIED;
        }
        if (mode != kind.autoMode && !setModeIfValid(kind.autoMode)) {
            return MAV_RESULT.MAV_RESULT_FAILED;
        }
        flight.missionStart();
        return MAV_RESULT.MAV_RESULT_ACCEPTED;
    }

    private static int missionTarget(MAVLinkMessage m) {
        if (m instanceof msg_mission_count x) {
            return x.target_system;
        } else if (m instanceof msg_mission_item_int x) {
            return x.target_system;
        } else if (m instanceof msg_mission_item x) {
            return x.target_system;
        } else if (m instanceof msg_mission_request_list x) {
            return x.target_system;
        } else if (m instanceof msg_mission_request_int x) {
            return x.target_system;
        } else if (m instanceof msg_mission_request x) {
            return x.target_system;
        } else if (m instanceof msg_mission_clear_all x) {
            return x.target_system;
        } else if (m instanceof msg_mission_ack x) {
            return x.target_system;
        }
        return -1;
    }

    private int arm(long now) {
        if (armed) {
            return MAV_RESULT.MAV_RESULT_ACCEPTED;
        }
        if (kind == VehicleKind.COPTER && mode == kind.autoMode) {
            text(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, "Arm: AUTO mode not armable");
            return MAV_RESULT.MAV_RESULT_FAILED;
        }
        if (!prearmPassed(now)) {
            text(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, "PreArm: Need Position Estimate");
            return MAV_RESULT.MAV_RESULT_FAILED;
        }
        armed = true;
        return MAV_RESULT.MAV_RESULT_ACCEPTED;
    }

    private int disarm(float force) {
        if (armed && position.hae() - home.hae() > 1 && (int) force != FORCE_DISARM) {
            text(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, "Disarm: vehicle is flying");
            return MAV_RESULT.MAV_RESULT_FAILED;
        }
        armed = false;
        flight.disarmed();
        return MAV_RESULT.MAV_RESULT_ACCEPTED;
    }

    private boolean setModeIfValid(long custom) {
        if (!kind.family.modes().containsKey(custom) || options.refuseModeChanges()) {
            return false;
        }
        if (custom == kind.autoMode && mode != kind.autoMode && !flight.autoAllowed()) {
            text(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, "Auto: Missing Takeoff Cmd");
            return false;
        }
        int from = mode;
        mode = (int) custom;
        flight.modeChanged(from, mode);
        return true;
    }

    private int setHome(msg_command_long c) {
        if (c.param1 == 1) {
            home = position;
        } else {
            if (!(Math.abs(c.param5) <= 90 && Math.abs(c.param6) <= 180)) {
                return MAV_RESULT.MAV_RESULT_DENIED;
            }
            home = Position.fromDegrees(c.param5, c.param6, c.param7);
        }
        return MAV_RESULT.MAV_RESULT_ACCEPTED;
    }

    private int setInterval(int msgid, float micros) {
        if (!options.messageIntervalSupported()) {
            return MAV_RESULT.MAV_RESULT_UNSUPPORTED;
        }
        if (!STREAMABLE.contains(msgid)) {
            return MAV_RESULT.MAV_RESULT_FAILED;
        }
        if (micros < 0 || (micros == 0 && kind.defaultStreamHz == 0)) {
            intervals.remove(msgid);
        } else {
            intervals.put(msgid, micros == 0 ? (long) (SECOND / kind.defaultStreamHz) : (long) (micros * 1000));
        }
        nextDue.remove(msgid);
        return MAV_RESULT.MAV_RESULT_ACCEPTED;
    }

    private void requestDataStream(msg_request_data_stream r) {
        Set<Integer> ids = switch (r.req_stream_id) {
            case MAV_DATA_STREAM.MAV_DATA_STREAM_ALL -> STREAMABLE;
            case MAV_DATA_STREAM.MAV_DATA_STREAM_EXTENDED_STATUS -> Set.of(msg_sys_status.MAVLINK_MSG_ID_SYS_STATUS,
                    msg_mission_current.MAVLINK_MSG_ID_MISSION_CURRENT, msg_extended_sys_state.MAVLINK_MSG_ID_EXTENDED_SYS_STATE);
            case MAV_DATA_STREAM.MAV_DATA_STREAM_POSITION -> Set.of(msg_global_position_int.MAVLINK_MSG_ID_GLOBAL_POSITION_INT);
            case MAV_DATA_STREAM.MAV_DATA_STREAM_EXTRA3 -> Set.of(msg_battery_status.MAVLINK_MSG_ID_BATTERY_STATUS,
                    msg_home_position.MAVLINK_MSG_ID_HOME_POSITION);
            default -> Set.of();
        };
        for (int id : ids) {
            if (r.start_stop == 0 || r.req_message_rate == 0) {
                intervals.remove(id);
            } else {
                intervals.put(id, SECOND / r.req_message_rate);
            }
            nextDue.remove(id);
        }
    }

    /** Answers the sender of the command, as ArduPilot does. */
    private void ack(msg_command_long c, int result) {
        msg_command_ack a = new msg_command_ack();
        a.command = c.command;
        a.result = (short) result;
        a.target_system = (short) c.sysid;
        a.target_component = (short) c.compid;
        out.accept(a);
    }

    private void send(MAVLinkMessage m) {
        if (!silent) {
            out.accept(m);
        }
    }

    /** The mission transfer's view of this vehicle. */
    private final class TransferHost implements MissionTransfer.Host {
        @Override
        public void send(MAVLinkMessage m) {
            SimVehicle.this.send(m);
        }

        @Override
        public void text(int severity, String text) {
            SimVehicle.this.text(severity, text);
        }

        @Override
        public boolean clearAllowed() {
            return !flight.flyingMission();
        }

        @Override
        public void missionChanged() {
            flight.missionChanged();
        }
    }

    /** The mission flight's view of this vehicle. */
    private final class FlightBody implements MissionFlight.Body {
        @Override
        public Position position() {
            return position;
        }

        @Override
        public void place(Position p) {
            position = p;
        }

        @Override
        public Position home() {
            return home;
        }

        @Override
        public boolean armed() {
            return armed;
        }

        @Override
        public int mode() {
            return mode;
        }

        @Override
        public void switchMode(int m) {
            mode = m;
        }

        @Override
        public void touchdown() {
            armed = false;
            flight.disarmed();
        }

        @Override
        public void send(MAVLinkMessage m) {
            SimVehicle.this.send(m);
        }

        @Override
        public void text(int severity, String text) {
            SimVehicle.this.text(severity, text);
        }
    }

    private void text(int severity, String text) {
        if (silent) {
            return;
        }
        msg_statustext t = new msg_statustext();
        t.severity = (short) severity;
        t.setText(text);
        out.accept(t);
    }

    private msg_heartbeat heartbeat() {
        msg_heartbeat hb = new msg_heartbeat();
        hb.type = (short) kind.mavType;
        hb.autopilot = MAV_AUTOPILOT.MAV_AUTOPILOT_ARDUPILOTMEGA;
        hb.base_mode = (short) (MAV_MODE_FLAG.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED | (armed ? MAV_MODE_FLAG.MAV_MODE_FLAG_SAFETY_ARMED : 0));
        hb.custom_mode = mode;
        hb.system_status = (short) (armed ? MAV_STATE.MAV_STATE_ACTIVE : MAV_STATE.MAV_STATE_STANDBY);
        hb.mavlink_version = 3;
        return hb;
    }

    /** Whether the pre-arm checks pass: after the warm-up, as ArduPilot once its EKF has settled. */
    private boolean prearmPassed(long now) {
        return now - bootNanos >= (long) (options.warmupSeconds() * 1e9);
    }

    private MAVLinkMessage telemetry(int msgid) {
        return switch (msgid) {
            case msg_sys_status.MAVLINK_MSG_ID_SYS_STATUS -> {
                msg_sys_status s = new msg_sys_status();
                s.voltage_battery = 12600;
                s.current_battery = (short) (armed ? 2800 : 0);
                s.battery_remaining = (byte) Math.round(battery);
                // ArduPilot reports its pre-arm checks as a sensor: present and enabled, healthy when they pass or when armed
                s.onboard_control_sensors_present = MAV_SYS_STATUS_SENSOR.MAV_SYS_STATUS_PREARM_CHECK;
                s.onboard_control_sensors_enabled = MAV_SYS_STATUS_SENSOR.MAV_SYS_STATUS_PREARM_CHECK;
                s.onboard_control_sensors_health = armed || prearmPassed(lastTick) ? MAV_SYS_STATUS_SENSOR.MAV_SYS_STATUS_PREARM_CHECK : 0;
                yield s;
            }
            case msg_global_position_int.MAVLINK_MSG_ID_GLOBAL_POSITION_INT -> {
                msg_global_position_int p = new msg_global_position_int();
                p.lat = MissionItem.degE7(position.latitudeDegrees());
                p.lon = MissionItem.degE7(position.longitudeDegrees());
                p.alt = (int) Math.round(position.hae() * 1000);
                p.relative_alt = (int) Math.round((position.hae() - home.hae()) * 1000);
                p.hdg = 65535;
                yield p;
            }
            case msg_home_position.MAVLINK_MSG_ID_HOME_POSITION -> {
                msg_home_position h = new msg_home_position();
                h.latitude = MissionItem.degE7(home.latitudeDegrees());
                h.longitude = MissionItem.degE7(home.longitudeDegrees());
                h.altitude = (int) Math.round(home.hae() * 1000);
                h.q = new float[] {1, 0, 0, 0};
                yield h;
            }
            case msg_extended_sys_state.MAVLINK_MSG_ID_EXTENDED_SYS_STATE -> {
                msg_extended_sys_state e = new msg_extended_sys_state();
                e.landed_state = (short) (position.hae() - home.hae() > 0.5 ? MAV_LANDED_STATE.MAV_LANDED_STATE_IN_AIR
                        : MAV_LANDED_STATE.MAV_LANDED_STATE_ON_GROUND);
                yield e;
            }
            case msg_battery_status.MAVLINK_MSG_ID_BATTERY_STATUS -> {
                msg_battery_status b = new msg_battery_status();
                b.battery_remaining = (byte) Math.round(battery);
                b.current_battery = (short) (armed ? 2800 : 0);
                b.voltages = new int[] {4200, 4200, 4200, 65535, 65535, 65535, 65535, 65535, 65535, 65535};
                yield b;
            }
            default -> flight.missionCurrent();
        };
    }
}
