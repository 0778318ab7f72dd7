package dolphin.sim;

import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.ardupilotmega.msg_ekf_status_report;
import com.MAVLink.common.msg_battery_status;
import com.MAVLink.common.msg_camera_information;
import com.MAVLink.common.msg_gimbal_manager_information;
import com.MAVLink.common.msg_command_ack;
import com.MAVLink.common.msg_command_long;
import com.MAVLink.common.msg_extended_sys_state;
import com.MAVLink.common.msg_file_transfer_protocol;
import com.MAVLink.common.msg_gps_raw_int;
import com.MAVLink.common.msg_home_position;
import com.MAVLink.common.msg_mission_current;
import com.MAVLink.common.msg_mission_set_current;
import com.MAVLink.common.msg_param_request_read;
import com.MAVLink.common.msg_param_value;
import com.MAVLink.common.msg_request_data_stream;
import com.MAVLink.common.msg_set_mode;
import com.MAVLink.common.msg_sys_status;
import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_DATA_STREAM;
import com.MAVLink.enums.MAV_MODE_FLAG;
import com.MAVLink.enums.MAV_RESULT;
import com.MAVLink.enums.MAV_SEVERITY;
import com.MAVLink.enums.MAV_STATE;
import com.MAVLink.enums.MAV_SYS_STATUS_SENSOR;
import com.MAVLink.enums.MAV_TYPE;
import com.MAVLink.enums.MISSION_STATE;
import com.MAVLink.minimal.msg_heartbeat;
import com.MAVLink.standard.msg_autopilot_version;
import com.MAVLink.standard.msg_global_position_int;
import dolphin.core.Position;
import dolphin.mavlink.Autopilot;
import dolphin.mavlink.VehicleFamily;
import dolphin.mission.model.Fence;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import dolphin.mission.model.RallyPoints;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.Consumer;
import java.util.function.Function;

/**
 * One simulated vehicle: the identity, link and command behaviour of its firmware ({@link VehicleKind},
 * whose {@link Firmware} says what differs between ArduCopter, ArduPlane, ArduRover and ArduSub) under
 * its autopilot ({@link SimAutopilot}: ArduPilot, or PX4 flying the same families' models). Driven by its {@link SimFleet}'s one thread; the public methods are synchronized, so
 * tests may read and change it from other threads.
 */
public final class SimVehicle {

    private static final Set<Integer> STREAMABLE = Set.of(msg_sys_status.MAVLINK_MSG_ID_SYS_STATUS,
            msg_global_position_int.MAVLINK_MSG_ID_GLOBAL_POSITION_INT, msg_mission_current.MAVLINK_MSG_ID_MISSION_CURRENT,
            msg_battery_status.MAVLINK_MSG_ID_BATTERY_STATUS, msg_home_position.MAVLINK_MSG_ID_HOME_POSITION,
            msg_extended_sys_state.MAVLINK_MSG_ID_EXTENDED_SYS_STATE, msg_ekf_status_report.MAVLINK_MSG_ID_EKF_STATUS_REPORT,
            msg_gps_raw_int.MAVLINK_MSG_ID_GPS_RAW_INT);
    private static final long SECOND = 1_000_000_000L;
    private static final int FORCE_DISARM = 21196;

    private final int sysid;
    private final VehicleKind kind;
    private final SimAutopilot autopilot;
    private final Firmware firmware;
    private final SimOptions options;
    private PositionEstimate estimate;
    private long boot;
    private final SimSensors sensors;
    private final boolean camera;
    private final Map<Integer, Long> intervals = new HashMap<>();
    private final Map<Integer, Long> nextDue = new HashMap<>();
    private final Outbox outbox;
    /** A ground station's heartbeat was heard: PX4 sends STATUSTEXT only from then on. */
    private boolean gcsHeard;
    /** Seconds armed on the ground without flying a mission, towards the firmware's preflight disarm. */
    private double armedIdle;
    private Consumer<MAVLinkMessage> out = m -> { };
    private long nextHeartbeat;
    private long lastTick;
    private int mode;
    private boolean modeToAnnounce;
    private boolean armed;
    private boolean silent;
    private double battery = 100;
    private final Craft craft;
    private Position home;
    private int commandsHandled;
    private final MissionStore missionStore;
    /** The mission as the protocol transfers it, which names its id (ItemStore.planId). */
    private final ItemStore missionList;
    private final MissionLists lists;
    private final FenceGuard fenceGuard = new FenceGuard();
    private final MissionFlight flight;
    private final SimFtpServer ftp;
    private final NavigationState navigation = new NavigationState();
    private final FaultSchedule faults;
    private final FaultHost faultHost = new Afflicted();
    /** Clock time of its first arming, from which its faults' times count; negative before it. */
    private long firstArmed = -1;
    /** The link cut by an {@link Outage}. */
    private boolean outage;
    /** An internal error reported since boot: ArduPilot's heartbeat then says MAV_STATE_CRITICAL. */
    private boolean internalErrors;

    SimVehicle(int sysid, VehicleKind kind, Position home, SimOptions options, long now) {
        this(sysid, kind, home, options, now, SimEquipment.NONE);
    }

    /** A vehicle with what {@code equipment} puts on system id {@code sysid}. */
    SimVehicle(int sysid, VehicleKind kind, Position home, SimOptions options, long now, SimEquipment equipment) {
        this.sysid = sysid;
        this.kind = kind;
        this.autopilot = SimAutopilot.of(options.autopilot());
        this.firmware = autopilot.firmware(kind);
        this.outbox = new Outbox(this::send, autopilot.reachedRepeats(), () -> gcsHeard || autopilot.textsBeforeGcs(),
                () -> lastTick);
        this.options = options;
        this.estimate = new PositionEstimate(now, options.warmupSeconds());
        this.boot = now;
        this.sensors = new SimSensors(equipment.sensorsOf(sysid), now);
        this.camera = equipment.cameraOn(sysid);
        this.home = home;
        this.craft = new Craft(home, firmware.performance(), s -> outbox.text(MAV_SEVERITY.MAV_SEVERITY_INFO, s));
        this.mode = firmware.bootMode();
        this.nextHeartbeat = now;
        this.lastTick = now;
        this.missionStore = new MissionStore(() -> this.home, options.missionCapacity(),
                firmware.family().firmware() == VehicleFamily.PLANE);
        TransferHost host = new TransferHost();
        this.missionList = autopilot.missionList(missionStore);
        this.lists = new MissionLists(missionList, missionStore, options.missionCapacity(), host,
                autopilot.transferRules());
        // PX4 serves FTP but has no @MISSION files: every list is unknown to it
        Function<MissionType, ItemStore> files = autopilot.missionFiles() ? lists::store : type -> null;
        this.ftp = new SimFtpServer(new MissionFiles(files, new MissionFileLoader(files, host)), this::send);
        this.flight = new MissionFlight(firmware, autopilot, missionStore, new FlightBody());
        this.faults = new FaultSchedule(options.faults(), sysid, kind, firmware);
        defaultStreams(now);
    }

    /** The streams a firmware sends before anyone asks (a plane's and a sub's). */
    private void defaultStreams(long now) {
        if (firmware.defaultStreamHz() > 0) {
            for (int id : STREAMABLE) {
                stream(id, (long) (SECOND / firmware.defaultStreamHz()), now);
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

    /** The autopilot it runs: ArduPilot or PX4. */
    public Autopilot autopilot() {
        return options.autopilot();
    }

    public synchronized int mode() {
        return mode;
    }

    public synchronized String modeName() {
        return firmware.modes().name(mode);
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
        return craft.position();
    }

    public synchronized Position home() {
        return home;
    }

    /** MAV_LANDED_STATE, as EXTENDED_SYS_STATE reports it. */
    public synchronized int landedState() {
        return firmware.landedState(craft.onGround(), flight.manoeuvreState());
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

    /**
     * The stored mission, home first (seq 0 is always the vehicle's home, as in ArduPilot; a PX4
     * vehicle's protocol leaves it out, its first item seq 0 on the wire).
     */
    public synchronized List<MissionItem> mission() {
        return missionStore.items();
    }

    /** The stored fence (docs/airspace.md). */
    public synchronized Fence fence() {
        return lists.fence();
    }

    /** The stored rally points. */
    public synchronized RallyPoints rallyPoints() {
        return lists.rally();
    }

    /** Camera items (IMAGE_START/STOP_CAPTURE, DO_DIGICAM_CONTROL, DO_SET_CAM_TRIGG_DIST) the missions ran. */
    public synchronized int cameraCommands() {
        return flight.cameraCommands();
    }

    /** The current mission item (seq), as MISSION_CURRENT reports it. */
    public synchronized int missionCurrent() {
        return flight.current();
    }

    /** MISSION_STATE: NO_MISSION, NOT_STARTED, ACTIVE or COMPLETE (ArduPilot never reports PAUSED). */
    public synchronized int missionState() {
        return flight.state();
    }

    /** Whether an upload is in progress. */
    public synchronized boolean missionUploading() {
        return lists.uploading();
    }

    /** Mode changes by "someone else", e.g. a pilot's switch: the ground station is not asked. */
    public synchronized void setMode(int customMode) {
        changeMode(customMode);
    }

    synchronized void tick(long now) {
        double dt = (now - lastTick) / 1e9;
        lastTick = now;
        if (modeToAnnounce) {
            announceMode();
        }
        if (armed) {
            battery = Math.max(0, battery - options.drainPercentPerMinute() * dt / 60);
        }
        lists.tick(now);
        ftp.tick(now);
        // before the flight, so that a fault beginning now holds it from this tick on
        faults.tick(now, firstArmed, dt, faultHost);
        flight.tick(dt, faults.holdsFlight(faultHost));
        preflightDisarm(dt);
        watchFence(now);
        if (firmware.needsPositionToArm()) {
            estimate.periodicReport(now, armed).ifPresent(s -> outbox.text(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, s));
        }
        outbox.flush();
        outbox.tick(now);
        if (cutOff()) {
            return;
        }
        // streams due with the heartbeat go out just before it, as SITL's do
        for (Map.Entry<Integer, Long> e : intervals.entrySet()) {
            long due = nextDue.getOrDefault(e.getKey(), now);
            if (now >= due) {
                telemetry(e.getKey()).ifPresent(out);
                nextDue.put(e.getKey(), nextOnGrid(due, e.getValue(), now));
            }
        }
        sensors.due(now, craft.position(), bootMillis(now)).forEach(out);
        if (now >= nextHeartbeat) {
            if (fenceGuard.enabled()) {
                out.accept(fenceGuard.status());
            }
            out.accept(heartbeat());
            nextHeartbeat = nextOnGrid(nextHeartbeat, SECOND, now);
        }
    }

    /** COM_DISARM_PRFLT: armed on the ground and not flying a mission, the vehicle disarms itself. */
    private void preflightDisarm(double dt) {
        double limit = firmware.preflightDisarmSeconds();
        if (limit <= 0 || !armed || !craft.onGround() || flight.flyingMission()) {
            armedIdle = 0;
            return;
        }
        armedIdle += dt;
        if (armedIdle >= limit) {
            disarmNow("Disarmed by auto preflight disarming");
        }
    }

    /** A breach of an enabled fence: ArduPilot's message and its default action, RTL (FENCE_ACTION 1). */
    private void watchFence(long now) {
        if (!fenceGuard.enabled()) {
            return;
        }
        switch (fenceGuard.check(lists.fence(), craft.position(), armed, now / 1_000_000)) {
            case BREACHED -> {
                outbox.text(MAV_SEVERITY.MAV_SEVERITY_NOTICE, "Polygon fence breached");
                outbox.flush();
                sendFenceStatus();
                // ArduSub takes no action on a breach (Sub::fence_checks_async): it has no RTL
                if (firmware.rtlMode().isPresent()) {
                    changeMode(firmware.rtlMode().getAsInt());
                    announceMode();
                }
            }
            case CLEARED -> {
                outbox.text(MAV_SEVERITY.MAV_SEVERITY_NOTICE, "Fence breach cleared");
                sendFenceStatus();
            }
            default -> {
            }
        }
    }

    /** FENCE_STATUS at once on a change, unless the vehicle is cut off (its telemetry lost). */
    private void sendFenceStatus() {
        if (!cutOff()) {
            out.accept(fenceGuard.status());
        }
    }

    /** The first time after {@code now} on the grid of {@code interval} through {@code due}: a late tick keeps the phase. */
    static long nextOnGrid(long due, long interval, long now) {
        return due + interval * ((now - due) / interval + 1);
    }

    synchronized void handle(MAVLinkMessage m, long now) {
        if (cutOff()) {
            return;
        }
        if (m instanceof msg_heartbeat h && h.type == MAV_TYPE.MAV_TYPE_GCS) {
            gcsHeard = true;
        }
        if (m instanceof msg_command_long c && c.target_system == sysid) {
            commandsHandled++;
            ack(c, command(c, now));
        } else if (m instanceof msg_set_mode s && s.target_system == sysid) {
            setModeIfValid(s.custom_mode);
        } else if (m instanceof msg_request_data_stream r && r.target_system == sysid) {
            requestDataStream(r, now);
        } else if (m instanceof msg_file_transfer_protocol f && f.target_system == sysid) {
            // a vehicle without FTP does not answer at all, as firmware built without it
            if (options.ftp()) {
                ftp.handle(f, now);
            }
        } else if (lists.handle(m, sysid, now)) {
            // a mission, fence or rally transfer
        } else if (m instanceof msg_mission_set_current s && s.target_system == sysid) {
            flight.setCurrentMessage(autopilot.storedSeq(s.seq));
        } else if (m instanceof msg_param_request_read r && r.target_system == sysid) {
            paramValue(r).ifPresent(this::send);
        }
        if (modeToAnnounce) {
            announceMode();
        }
        outbox.flush();
    }

    private int command(msg_command_long c, long now) {
        return switch (c.command) {
            case MAV_CMD.MAV_CMD_COMPONENT_ARM_DISARM -> c.param1 == 1 ? arm(now) : disarm(c.param2);
            case MAV_CMD.MAV_CMD_DO_SET_MODE -> SimAutopilot.customModeFlag(c.param1)
                    ? autopilot.setMode(c.param2, c.param3, this::setModeIfValid) : MAV_RESULT.MAV_RESULT_FAILED;
            case MAV_CMD.MAV_CMD_DO_SET_HOME -> setHome(c, now);
            case MAV_CMD.MAV_CMD_BATTERY_RESET -> {
                // param1 is a mask of battery instances; this vehicle has instance 0 only
                if (((int) c.param1 & 1) == 0) {
                    yield MAV_RESULT.MAV_RESULT_FAILED;
                }
                battery = Math.max(0, Math.min(100, c.param2));
                yield MAV_RESULT.MAV_RESULT_ACCEPTED;
            }
            case MAV_CMD.MAV_CMD_SET_MESSAGE_INTERVAL -> setInterval((int) c.param1, c.param2, now);
            case MAV_CMD.MAV_CMD_REQUEST_MESSAGE -> requestMessage((int) c.param1, now);
            case MAV_CMD.MAV_CMD_REQUEST_AUTOPILOT_CAPABILITIES -> {
                // GCS_MAVLINK::handle_command_request_autopilot_capabilities: p1 must be 1
                if (c.param1 != 1) {
                    yield MAV_RESULT.MAV_RESULT_FAILED;
                }
                outbox.requested(autopilot.version(kind, options.ftp()));
                yield MAV_RESULT.MAV_RESULT_ACCEPTED;
            }
            case MAV_CMD.MAV_CMD_GET_HOME_POSITION -> {
                if (!estimate.ready(lastTick)) {
                    yield MAV_RESULT.MAV_RESULT_FAILED; // no home yet
                }
                telemetry(msg_home_position.MAVLINK_MSG_ID_HOME_POSITION).ifPresent(out);
                yield MAV_RESULT.MAV_RESULT_ACCEPTED;
            }
            case MAV_CMD.MAV_CMD_MISSION_START -> autopilot.armsOnMissionStart() ? armAndStart(c, now) : missionStart(c);
            case MAV_CMD.MAV_CMD_DO_FENCE_ENABLE -> {
                fenceGuard.enable(c.param1 == 1);
                yield MAV_RESULT.MAV_RESULT_ACCEPTED;
            }
            case MAV_CMD.MAV_CMD_DO_SET_MISSION_CURRENT -> flight.setCurrentCommand(autopilot.storedSeq((int) c.param1), c.param2 == 1);
            case MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH -> firmware.rtlMode().isEmpty() ? MAV_RESULT.MAV_RESULT_UNSUPPORTED
                    : setModeIfValid(firmware.rtlMode().getAsInt()) ? MAV_RESULT.MAV_RESULT_ACCEPTED : MAV_RESULT.MAV_RESULT_FAILED;
            case MAV_CMD.MAV_CMD_DO_AUX_FUNCTION -> firmware.auxFunction((int) c.param1, (int) c.param2, armed, now);
            case MAV_CMD.MAV_CMD_NAV_LAND -> firmware.landMode().isPresent() && setModeIfValid(firmware.landMode().getAsInt())
                    ? MAV_RESULT.MAV_RESULT_ACCEPTED : MAV_RESULT.MAV_RESULT_UNSUPPORTED;
            default -> MAV_RESULT.MAV_RESULT_UNSUPPORTED;
        };
    }

    /**
     * GCS_MAVLINK::handle_command_request_message. CAMERA_INFORMATION and GIMBAL_MANAGER_INFORMATION are
     * messages ArduPilot knows, so they are ACCEPTED either way; AP_Camera then sends one per camera,
     * none without a camera, and the simulated vehicles carry no gimbal (docs/decisions.md). PX4 denies
     * what it does not send ({@link SimAutopilot#notSent}).
     */
    private int requestMessage(int msgid, long now) {
        if (msgid == msg_camera_information.MAVLINK_MSG_ID_CAMERA_INFORMATION) {
            if (camera) {
                outbox.requested(SimCamera.information(bootMillis(now)));
                return MAV_RESULT.MAV_RESULT_ACCEPTED;
            }
            return autopilot.notSent(MAV_RESULT.MAV_RESULT_ACCEPTED);
        }
        if (msgid == msg_gimbal_manager_information.MAVLINK_MSG_ID_GIMBAL_MANAGER_INFORMATION) {
            return autopilot.notSent(MAV_RESULT.MAV_RESULT_ACCEPTED);
        }
        if (msgid == msg_autopilot_version.MAVLINK_MSG_ID_AUTOPILOT_VERSION) {
            outbox.requested(autopilot.version(kind, options.ftp()));
            return MAV_RESULT.MAV_RESULT_ACCEPTED;
        }
        if (!STREAMABLE.contains(msgid)) {
            return autopilot.notSent(MAV_RESULT.MAV_RESULT_FAILED);
        }
        telemetry(msgid).ifPresent(out);
        return MAV_RESULT.MAV_RESULT_ACCEPTED;
    }

    /**
     * PARAM_REQUEST_READ by name (param_index -1) or by index (GCS_MAVLINK::param_io_timer): the
     * PARAM_VALUE, with the index asked for and the count of the firmware's parameters; a parameter
     * it does not have gets no answer, as older ArduPilot (4.8 sends PARAM_ERROR).
     */
    private Optional<msg_param_value> paramValue(msg_param_request_read r) {
        List<FirmwareParam> params = firmware.params();
        String name = r.getParam_Id();
        int index = r.param_index;
        Optional<FirmwareParam> found = index >= 0
                ? (index < params.size() ? Optional.of(params.get(index)) : Optional.empty())
                : params.stream().filter(p -> p.name().equals(name)).findFirst();
        return found.map(p -> {
            msg_param_value v = new msg_param_value();
            v.setParam_Id(p.name());
            v.param_value = p.value();
            v.param_type = (short) p.type();
            v.param_count = params.size();
            // uint16 on the wire: ArduPilot's -1 for a read by name arrives as 65535
            v.param_index = index & 0xFFFF;
            return v;
        });
    }

    /** time_boot_ms: clock milliseconds since this vehicle booted. */
    private long bootMillis(long now) {
        return (now - boot) / 1_000_000;
    }

    /** GCS_MAVLINK_Copter::handle_MAV_CMD_MISSION_START: p1 = p2 = 0, switch to AUTO, auto_armed. */
    private int missionStart(msg_command_long c) {
        if (c.param1 != 0 || c.param2 != 0) {
            return MAV_RESULT.MAV_RESULT_DENIED;
        }
        if (mode != firmware.autoMode() && !setModeIfValid(firmware.autoMode())) {
            return MAV_RESULT.MAV_RESULT_FAILED;
        }
        flight.missionStart();
        return MAV_RESULT.MAV_RESULT_ACCEPTED;
    }

    /**
     * PX4's Commander: with a feasible mission and -1 <= p1 < its item count, the mission goes on from
     * item p1 (-1: where it is) in AUTO.MISSION, the vehicle armed if it was not; else DENIED, said when
     * there is no valid mission.
     */
    private int armAndStart(msg_command_long c, long now) {
        if (flight.state() == MISSION_STATE.MISSION_STATE_NO_MISSION) {
            outbox.text(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, "Mission start denied! No valid mission");
            return MAV_RESULT.MAV_RESULT_DENIED;
        }
        if (c.param1 < -1 || c.param1 >= missionStore.count() - 1) {
            return MAV_RESULT.MAV_RESULT_DENIED;
        }
        if (c.param1 >= 0) {
            flight.setCurrentCommand(autopilot.storedSeq((int) c.param1), false);
        }
        if (!setModeIfValid(firmware.autoMode())) {
            return MAV_RESULT.MAV_RESULT_FAILED;
        }
        if (!armed && arm(now, "Armed by mission start") != MAV_RESULT.MAV_RESULT_ACCEPTED) {
            return MAV_RESULT.MAV_RESULT_FAILED;
        }
        flight.missionStart();
        return MAV_RESULT.MAV_RESULT_ACCEPTED;
    }

    private int arm(long now) {
        return arm(now, firmware.armedText());
    }

    /** Arms, saying {@code text}, unless the firmware refuses. */
    private int arm(long now, String text) {
        if (armed) {
            return MAV_RESULT.MAV_RESULT_ACCEPTED;
        }
        var refusal = firmware.armRefusal(mode, new MissionView(missionStore.items(), flight.current(),
                flight.state() == MISSION_STATE.MISSION_STATE_ACTIVE));
        if (refusal.isPresent()) {
            outbox.text(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, refusal.get());
            return MAV_RESULT.MAV_RESULT_FAILED;
        }
        if (firmware.needsPositionToArm() && !estimate.ready(now)) {
            outbox.text(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, PositionEstimate.FAILURE);
            return MAV_RESULT.MAV_RESULT_FAILED;
        }
        armed = true;
        if (firstArmed < 0) {
            firstArmed = now;
        }
        outbox.text(MAV_SEVERITY.MAV_SEVERITY_INFO, text);
        return MAV_RESULT.MAV_RESULT_ACCEPTED;
    }

    private int disarm(float force) {
        if (armed && firmware.disarmsOnlyLanded() && !craft.onGround() && !craft.contact() && (int) force != FORCE_DISARM) {
            outbox.text(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, "Disarm: vehicle is flying");
            return MAV_RESULT.MAV_RESULT_FAILED;
        }
        disarmNow(firmware.disarmedText());
        return MAV_RESULT.MAV_RESULT_ACCEPTED;
    }

    private void disarmNow(String text) {
        if (armed) {
            outbox.text(MAV_SEVERITY.MAV_SEVERITY_INFO, text);
        }
        // disarmed, EKF3 takes lane 0 again, and AP_AHRS says so (copter-fault-gps: after "Disarming motors")
        if (navigation.primaryLane() != 0) {
            navigation.primaryLane(0);
            outbox.text(FaultTable.PRIMARY_CHANGED_SEVERITY, String.format(Locale.ROOT, FaultTable.PRIMARY_CHANGED, 0));
        }
        armed = false;
        craft.settle();
        flight.disarmed();
    }

    private boolean setModeIfValid(long custom) {
        if (!firmware.modes().contains(custom) || options.refuseModeChanges()) {
            return false;
        }
        if (custom != mode) {
            var refusal = firmware.modeRefusal((int) custom, estimate.ready(lastTick), missionStore.count() > 1, armed, lastTick);
            if (refusal.isPresent()) {
                outbox.text(MAV_SEVERITY.MAV_SEVERITY_WARNING, refusal.get());
                return false;
            }
        }
        if (custom == firmware.autoMode() && mode != firmware.autoMode() && !flight.autoAllowed()) {
            outbox.text(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, "Auto: Missing Takeoff Cmd");
            return false;
        }
        changeMode((int) custom);
        return true;
    }

    /** The heartbeat announcing a new mode goes out at once, after the answer to the command that set it. */
    private void changeMode(int to) {
        int from = mode;
        mode = to;
        if (to != from) {
            modeToAnnounce = true;
        }
        flight.modeChanged(from, mode);
    }

    private void announceMode() {
        modeToAnnounce = false;
        send(heartbeat());
    }

    /** Home is the current position (p1 = 1) or the one given; with no position estimate yet, there is none to set. */
    private int setHome(msg_command_long c, long now) {
        if (!estimate.ready(now)) {
            return MAV_RESULT.MAV_RESULT_FAILED;
        }
        if (c.param1 == 1) {
            home = craft.position();
        } else {
            if (!(Math.abs(c.param5) <= 90 && Math.abs(c.param6) <= 180)) {
                return MAV_RESULT.MAV_RESULT_DENIED;
            }
            // to degE7 as GCS_MAVLINK::convert_COMMAND_LONG_to_COMMAND_INT does: in float, ArduPilot being
            // built with -fsingle-precision-constant, and truncated (40.44423294 becomes 404442336, not 404442329)
            int lat = (int) (c.param5 * 1e7f);
            int lon = (int) (c.param6 * 1e7f);
            home = Position.fromDegrees(lat * 1e-7, lon * 1e-7, c.param7);
        }
        return MAV_RESULT.MAV_RESULT_ACCEPTED;
    }

    private int setInterval(int msgid, float micros, long now) {
        if (!options.messageIntervalSupported()) {
            return MAV_RESULT.MAV_RESULT_UNSUPPORTED;
        }
        if (!STREAMABLE.contains(msgid)) {
            return MAV_RESULT.MAV_RESULT_FAILED;
        }
        if (micros < 0 || (micros == 0 && firmware.defaultStreamHz() == 0)) {
            intervals.remove(msgid);
            nextDue.remove(msgid);
        } else {
            stream(msgid, micros == 0 ? (long) (SECOND / firmware.defaultStreamHz()) : (long) (micros * 1000), now);
        }
        return MAV_RESULT.MAV_RESULT_ACCEPTED;
    }

    private void requestDataStream(msg_request_data_stream r, long now) {
        Set<Integer> ids = switch (r.req_stream_id) {
            case MAV_DATA_STREAM.MAV_DATA_STREAM_ALL -> STREAMABLE;
            case MAV_DATA_STREAM.MAV_DATA_STREAM_EXTENDED_STATUS -> Set.of(msg_sys_status.MAVLINK_MSG_ID_SYS_STATUS,
                    msg_mission_current.MAVLINK_MSG_ID_MISSION_CURRENT, msg_extended_sys_state.MAVLINK_MSG_ID_EXTENDED_SYS_STATE,
                    msg_gps_raw_int.MAVLINK_MSG_ID_GPS_RAW_INT);
            case MAV_DATA_STREAM.MAV_DATA_STREAM_POSITION -> Set.of(msg_global_position_int.MAVLINK_MSG_ID_GLOBAL_POSITION_INT);
            case MAV_DATA_STREAM.MAV_DATA_STREAM_EXTRA3 -> Set.of(msg_battery_status.MAVLINK_MSG_ID_BATTERY_STATUS,
                    msg_home_position.MAVLINK_MSG_ID_HOME_POSITION, msg_ekf_status_report.MAVLINK_MSG_ID_EKF_STATUS_REPORT);
            default -> Set.of();
        };
        for (int id : ids) {
            if (r.start_stop == 0 || r.req_message_rate == 0) {
                intervals.remove(id);
                nextDue.remove(id);
            } else {
                stream(id, SECOND / r.req_message_rate, now);
            }
        }
    }

    /**
     * Streams message {@code id} every {@code interval} nanoseconds, in step with the heartbeat (the
     * first one on the heartbeat's grid of that interval): ArduPilot sends messages of one rate
     * together, so a 1 Hz stream goes out with each heartbeat.
     */
    private void stream(int id, long interval, long now) {
        intervals.put(id, interval);
        long ahead = Math.floorMod(nextHeartbeat - now, interval);
        nextDue.put(id, now + ahead);
    }

    /** Answers the sender of the command, as ArduPilot does. */
    private void ack(msg_command_long c, int result) {
        msg_command_ack a = new msg_command_ack();
        a.command = c.command;
        a.result = (short) result;
        a.target_system = (short) c.sysid;
        a.target_component = (short) c.compid;
        send(a);
    }

    private void send(MAVLinkMessage m) {
        if (!cutOff()) {
            out.accept(m);
        }
    }

    /**
     * Sends nothing and hears nothing: silenced, or deeper than the dive silence, as a sub's radio
     * is under water.
     */
    private boolean cutOff() {
        return silent || outage || craft.depth() > options.diveSilenceMetres();
    }

    /**
     * Reboots at clock time {@code now}, as ArduPilot after MAV_CMD_PREFLIGHT_REBOOT_SHUTDOWN: time
     * since boot from 0, its warm-up again, disarmed (motors stopped: a vehicle in the air comes
     * down, see {@link Reboot}) and in its boot mode, its requested streams forgotten, its mission
     * stopped with no current item, no failsafe or internal error on, EKF3 on lane 0, what its
     * firmware keeps as at boot (a helicopter's motor interlock on). What it stores
     * (mission, fence, rally points), its home, its battery and its GPS receiver's state stay.
     */
    private void reboot(long now) {
        boot = now;
        estimate = new PositionEstimate(now, options.warmupSeconds());
        armed = false;
        mode = firmware.bootMode();
        modeToAnnounce = false;
        nextHeartbeat = now;
        flight.rebooted();
        firmware.rebooted();
        navigation.failsafe(false);
        navigation.primaryLane(0);
        internalErrors = false;
        resetStreams();
        defaultStreams(now);
    }

    /** The mission transfer's view of this vehicle. */
    private final class TransferHost implements MissionItemProtocol.Host {
        @Override
        public void send(MAVLinkMessage m) {
            SimVehicle.this.send(m);
        }

        @Override
        public void text(int severity, String text) {
            outbox.text(severity, text);
        }

        @Override
        public boolean clearAllowed() {
            return !flight.flyingMission();
        }

        @Override
        public void changed(MissionType type) {
            if (type == MissionType.MISSION) {
                flight.missionChanged(missionList.planId());
            }
        }
    }

    /** The mission flight's view of this vehicle. */
    private class FlightBody implements MissionFlight.Body {
        @Override
        public Craft craft() {
            return craft;
        }

        @Override
        public Position home() {
            return home;
        }

        @Override
        public Fence fence() {
            return lists.fence();
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
            changeMode(m);
            announceMode();
        }

        @Override
        public void disarm() {
            disarmNow(firmware.landedDisarmText());
        }

        @Override
        public void text(int severity, String text) {
            outbox.text(severity, text);
        }

        @Override
        public void reached(int seq) {
            outbox.reached(autopilot.wireSeq(seq));
        }

        @Override
        public void flush() {
            outbox.flush();
        }

        @Override
        public void send(MAVLinkMessage m) {
            SimVehicle.this.send(m);
        }

        @Override
        public void internalError(String text) {
            if (!internalErrors) {
                internalErrors = true;
                outbox.text(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, text);
            }
        }
    }

    /** The faults' view of this vehicle: the flight's, and more. */
    private final class Afflicted extends FlightBody implements FaultHost {
        @Override
        public Firmware firmware() {
            return firmware;
        }

        @Override
        public boolean flightMoves() {
            return flight.movesIn(mode);
        }

        @Override
        public boolean setMode(int m) {
            boolean set = setModeIfValid(m);
            if (modeToAnnounce) {
                announceMode();
            }
            return set;
        }

        @Override
        public void pauseFlight(double seconds) {
            flight.pauseMode(seconds);
        }

        @Override
        public NavigationState navigation() {
            return navigation;
        }

        @Override
        public void cutOff(boolean cut) {
            outage = cut;
        }

        @Override
        public void reboot() {
            SimVehicle.this.reboot(lastTick);
        }
    }

    private msg_heartbeat heartbeat() {
        msg_heartbeat hb = new msg_heartbeat();
        hb.type = (short) firmware.mavType();
        hb.autopilot = (short) autopilot.mavAutopilot();
        hb.base_mode = (short) (MAV_MODE_FLAG.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED | (armed ? MAV_MODE_FLAG.MAV_MODE_FLAG_SAFETY_ARMED : 0));
        hb.custom_mode = mode;
        hb.system_status = (short) (navigation.failsafe() || internalErrors ? MAV_STATE.MAV_STATE_CRITICAL
                : firmware.systemStatus(armed, craft.onGround()));
        hb.mavlink_version = 3;
        return hb;
    }

    /** What a stream or a request sends of message {@code msgid}; nothing for a home not known yet. */
    private Optional<MAVLinkMessage> telemetry(int msgid) {
        boolean located = estimate.ready(lastTick);
        return switch (msgid) {
            case msg_sys_status.MAVLINK_MSG_ID_SYS_STATUS -> {
                msg_sys_status s = new msg_sys_status();
                s.voltage_battery = 12600;
                s.current_battery = (short) (armed ? 2800 : 0);
                s.battery_remaining = (byte) Math.round(battery);
                // ArduPilot reports its pre-arm checks as a sensor: present and enabled, healthy when they pass or when armed
                s.onboard_control_sensors_present = MAV_SYS_STATUS_SENSOR.MAV_SYS_STATUS_PREARM_CHECK;
                s.onboard_control_sensors_enabled = MAV_SYS_STATUS_SENSOR.MAV_SYS_STATUS_PREARM_CHECK;
                s.onboard_control_sensors_health = armed || located ? MAV_SYS_STATUS_SENSOR.MAV_SYS_STATUS_PREARM_CHECK : 0;
                yield Optional.of(s);
            }
            case msg_global_position_int.MAVLINK_MSG_ID_GLOBAL_POSITION_INT -> {
                // without a position estimate ArduPilot sends zeros
                msg_global_position_int p = new msg_global_position_int();
                Position position = craft.position();
                if (located) {
                    p.lat = MissionItem.degE7(position.latitudeDegrees());
                    p.lon = MissionItem.degE7(position.longitudeDegrees());
                    p.alt = (int) Math.round(position.hae() * 1000);
                    p.relative_alt = (int) Math.round((position.hae() - home.hae()) * 1000);
                    // centidegrees 0..35999, as ArduPilot sends its yaw
                    p.hdg = (int) Math.floorMod(Math.round(Math.toDegrees(craft.heading()) * 100), 36000);
                } else {
                    p.hdg = 65535;
                }
                p.time_boot_ms = bootMillis(lastTick);
                yield Optional.of(p);
            }
            case msg_home_position.MAVLINK_MSG_ID_HOME_POSITION -> {
                if (!located) {
                    yield Optional.empty();
                }
                msg_home_position h = new msg_home_position();
                h.latitude = MissionItem.degE7(home.latitudeDegrees());
                h.longitude = MissionItem.degE7(home.longitudeDegrees());
                h.altitude = (int) Math.round(home.hae() * 1000);
                h.q = new float[] {1, 0, 0, 0};
                yield Optional.of(h);
            }
            case msg_ekf_status_report.MAVLINK_MSG_ID_EKF_STATUS_REPORT -> {
                msg_ekf_status_report e = new msg_ekf_status_report();
                e.flags = navigation.ekfFlags(located);
                yield Optional.of(e);
            }
            case msg_gps_raw_int.MAVLINK_MSG_ID_GPS_RAW_INT -> Optional.of(navigation.gpsRaw(located, craft.position(), bootMillis(lastTick)));
            case msg_extended_sys_state.MAVLINK_MSG_ID_EXTENDED_SYS_STATE -> {
                msg_extended_sys_state e = new msg_extended_sys_state();
                e.landed_state = (short) firmware.landedState(craft.onGround(), flight.manoeuvreState());
                e.vtol_state = (short) firmware.vtolState(mode, craft.onGround());
                yield Optional.of(e);
            }
            case msg_battery_status.MAVLINK_MSG_ID_BATTERY_STATUS -> {
                msg_battery_status b = new msg_battery_status();
                b.battery_remaining = (byte) Math.round(battery);
                b.current_battery = (short) (armed ? 2800 : 0);
                b.voltages = new int[] {4200, 4200, 4200, 65535, 65535, 65535, 65535, 65535, 65535, 65535};
                yield Optional.of(b);
            }
            default -> Optional.of(flight.missionCurrent());
        };
    }
}
