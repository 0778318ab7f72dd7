package dolphin.mission.flight

import com.MAVLink.Messages.MAVLinkMessage
import com.MAVLink.common.msg_mission_current
import com.MAVLink.common.msg_mission_item_reached
import com.MAVLink.common.msg_statustext
import com.MAVLink.common.msg_mission_set_current
import com.MAVLink.common.msg_sys_status
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_VTOL_STATE
import com.MAVLink.enums.MAV_LANDED_STATE
import com.MAVLink.enums.MAV_RESULT
import com.MAVLink.enums.MAV_SEVERITY
import com.MAVLink.enums.MAV_SYS_STATUS_SENSOR
import com.MAVLink.enums.MISSION_STATE
import com.MAVLink.minimal.msg_heartbeat
import dolphin.core.AbstractNode
import dolphin.core.ManualClock
import dolphin.core.Payload
import dolphin.core.Position
import dolphin.core.VehicleEvent
import dolphin.mavlink.CommandResult
import dolphin.mavlink.Autopilot
import dolphin.mavlink.Px4Modes
import dolphin.mavlink.VehicleFamily
import dolphin.mavlink.VehicleState
import dolphin.mission.model.MissionItem
import dolphin.mission.model.MissionType
import dolphin.mission.transfer.TransferResult
import java.util.concurrent.CompletableFuture

/**
 * The vehicle a MissionExecutor flies, as its narrow {@link MissionVehicle} view, with no link: its
 * telemetry is a {@link VehicleState} the spec sets step by step; each command and transfer is
 * recorded with the clock time and returns a future the spec completes ({@link #answer},
 * {@link #accept}, {@link #completeUpload}, ...). With {@link #autopilot} on, it answers as an
 * ArduPilot vehicle that does what it is told: every command accepted at once, its effect on the
 * telemetry (mode, armed, home, current item, mission state), uploads stored and downloads
 * answered from them; {@link #answers} overrides single commands.
 */
class FakeFlightVehicle implements MissionVehicle {

    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)
    static final int PREARM = MAV_SYS_STATUS_SENSOR.MAV_SYS_STATUS_PREARM_CHECK
    /** An answer in {@link #answers}: the vehicle does it, but its COMMAND_ACK never arrives (NO_ACK after 5 attempts). */
    static final int DONE_WITHOUT_ACK = -100

    /** One COMMAND_LONG sent, at a clock time, with the future its COMMAND_ACK completes. */
    static class Command {
        final double time
        final int command
        final float[] params
        final String text
        final CompletableFuture<CommandResult> answer = new CompletableFuture<>()

        Command(double time, int command, float[] params, String text) {
            this.time = time
            this.command = command
            this.params = params
            this.text = text
        }

        String toString() { "${seconds(time)} ${text}" }
    }

    /** One upload or download asked for, at a clock time, with the future its end completes. */
    static class Transfer {
        final double time
        final boolean upload
        final MissionType type
        final List<MissionItem> items
        final CompletableFuture<TransferResult> result = new CompletableFuture<>()

        Transfer(double time, boolean upload, MissionType type, List<MissionItem> items) {
            this.time = time
            this.upload = upload
            this.type = type
            this.items = items
        }

        String toString() {
            "${seconds(time)} " + (upload ? "upload ${type.label()}: ${items.size()} items" : "download ${type.label()}")
        }
    }

    /** The node the executor is allocated; the spec may lose it. */
    static class VehicleNode extends AbstractNode {
        volatile boolean connected = true

        VehicleNode(String id) {
            super(id, 'UAV', Payload.NONE)
        }

        @Override
        Position getPosition() { null }

        @Override
        boolean isConnected() { connected }

        @Override
        void release() {}
    }

    final ManualClock clock
    final String id
    final int system
    final int component = 1
    final VehicleFamily family
    final VehicleNode node
    VehicleState state
    MissionExecutorConfig executorConfig = MissionExecutorConfig.DEFAULT
    /** Answers everything at once as a willing ArduPilot vehicle. */
    boolean autopilot
    /**
     * Answers by command text ("ARM", "DO_SET_MODE GUIDED"): a MAV_RESULT (its effect with ACCEPTED), NO_ACK (none after
     * 5 attempts, no effect), DONE_WITHOUT_ACK, or a closure given the Command, which answers it or not.
     */
    Map<String, Object> answers = [:]
    /** Answers to transfers, by "upload fence", "download mission", ...: a closure given the Transfer (or the vehicle and the Transfer). */
    Map<String, Closure> transferAnswers = [:]
    /** The lists the vehicle holds. */
    final Map<MissionType, List<MissionItem>> stored = [:]

    final List<Command> commands = []
    final List<Transfer> transfers = []
    /** Everything the executor did to the vehicle, in order: "0.0 DO_SET_MODE GUIDED", "0.0 upload mission: 4 items", "1.0 MISSION_SET_CURRENT 2". */
    final List<String> log = []
    /** flying() and landed() calls: "flying hop", "landed hop". */
    final List<String> executors = []
    int wakes
    private MissionExecutor current

    FakeFlightVehicle(ManualClock clock, String id = '1', VehicleFamily family = VehicleFamily.COPTER,
                      Autopilot firmware = Autopilot.ARDUPILOT) {
        this.clock = clock
        this.id = id
        this.system = id as int
        this.family = family
        this.node = new VehicleNode(id)
        this.state = VehicleState.initial(firmware, family)
        heartbeat(false, firmware == Autopilot.PX4 ? 'AUTO.LOITER' : family.firmware() == VehicleFamily.COPTER ? 'STABILIZE' : 'MANUAL')
        if (firmware == Autopilot.ARDUPILOT && family.firmware() == VehicleFamily.PLANE) {
            // ArduPlane's EXTENDED_SYS_STATE, which the executor awaits to tell a QuadPlane
            state = state.withExtendedState(MAV_LANDED_STATE.MAV_LANDED_STATE_ON_GROUND, family == VehicleFamily.VTOL
                    ? MAV_VTOL_STATE.MAV_VTOL_STATE_MC : MAV_VTOL_STATE.MAV_VTOL_STATE_UNDEFINED)
        }
    }

    static String seconds(double t) {
        String.format(Locale.ROOT, '%.1f', t)
    }

    // ---- MissionVehicle

    @Override
    String vehicleId() { id }

    @Override
    int groundSystem() { 208 }

    @Override
    String silence() { '' }

    @Override
    dolphin.mavlink.RoundTrip roundTrip() { new dolphin.mavlink.RoundTrip() }

    @Override
    Optional<Boolean> offersFtp() { Optional.empty() }

    @Override
    boolean throughRadio() { false }

    @Override
    int radioBufferFree() { -1 }

    @Override
    dolphin.mavlink.LinkRequests linkRequests() { new dolphin.mavlink.LinkRequests() }

    @Override
    dolphin.core.Position home() { state.home() }

    @Override
    void askHome() { }

    @Override
    VehicleFamily family() { family }

    @Override
    Autopilot autopilot() { state.autopilot() }

    @Override
    void askWhatItOffers() { }

    @Override
    int unansweredAsks() { 0 }

    /** Where a transfer in progress stands, as a spec sets it. */
    dolphin.mission.transfer.TransferStatus transferStatus

    @Override
    Optional<dolphin.mission.transfer.TransferStatus> transfer() { Optional.ofNullable(transferStatus) }

    @Override
    int system() { system }

    @Override
    int component() { component }

    @Override
    VehicleState state() { state }

    @Override
    MissionExecutorConfig executorConfig() { executorConfig }

    @Override
    CompletableFuture<CommandResult> command(int command, float... params) {
        def c = new Command(clock.seconds(), command, params, describe(command, params))
        commands << c
        log << c.toString()
        def given = answers[c.text]
        if (given instanceof Closure) {
            given(c)
        } else if (given == DONE_WITHOUT_ACK) {
            effect(c)
            answer(c, CommandResult.NO_ACK)
        } else if (given != null) {
            answer(c, given as int)
        } else if (autopilot) {
            accept(c)
        }
        c.answer
    }

    /** The vehicle's parameters by name; one not here is not answered (the read completes empty). */
    Map<String, Double> parameters = [:]

    @Override
    CompletableFuture<OptionalDouble> parameter(String name) {
        log << "${seconds(clock.seconds())} PARAM_REQUEST_READ ${name}".toString()
        Double value = parameters[name]
        CompletableFuture.completedFuture(value == null ? OptionalDouble.empty() : OptionalDouble.of(value))
    }

    @Override
    void send(MAVLinkMessage message) {
        log << "${seconds(clock.seconds())} ${message instanceof msg_mission_set_current ? 'MISSION_SET_CURRENT ' + message.seq : message.class.simpleName}".toString()
    }

    @Override
    CompletableFuture<TransferResult> upload(MissionType type, List<MissionItem> items) {
        queued(new Transfer(clock.seconds(), true, type, List.copyOf(items)))
    }

    @Override
    CompletableFuture<TransferResult> download(MissionType type) {
        queued(new Transfer(clock.seconds(), false, type, null))
    }

    private CompletableFuture<TransferResult> queued(Transfer t) {
        transfers << t
        log << t.toString()
        Closure given = transferAnswers["${t.upload ? 'upload' : 'download'} ${t.type.label()}".toString()]
        if (given != null) {
            given.maximumNumberOfParameters == 2 ? given(this, t) : given(t)
        } else if (autopilot) {
            t.upload ? completeUpload(t) : completeDownload(t)
        }
        t.result
    }

    @Override
    void wake() { wakes++ }

    /** The vehicle events the executor raised, as "KIND text". */
    List<String> events = []

    @Override
    void event(VehicleEvent.EventKind kind, String text) {
        events << "${kind} ${text}".toString()
    }

    @Override
    void flying(MissionExecutor executor) {
        executors << "flying ${executor.mission().id}".toString()
        current = executor
    }

    @Override
    void landed(MissionExecutor executor) {
        executors << "landed ${executor.mission().id}".toString()
        if (current.is(executor)) {
            current = null
        }
    }

    // ---- answering commands

    /** The oldest command not answered yet. */
    Command pending() {
        def c = commands.find { !it.answer.done }
        assert c != null: "no command waits for an answer; sent: ${commands}"
        c
    }

    /** Answers the oldest waiting command with ACCEPTED, and does it. */
    void accept() { accept(pending()) }

    void accept(Command c) {
        effect(c)
        answer(c, MAV_RESULT.MAV_RESULT_ACCEPTED)
    }

    /** Answers the oldest waiting command: a MAV_RESULT, or NO_ACK (none after 5 attempts). */
    void answer(int result) { answer(pending(), result) }

    void answer(Command c, int result) {
        if (result == MAV_RESULT.MAV_RESULT_ACCEPTED) {
            effect(c)
        }
        c.answer.complete(new CommandResult(c.command, result, result == CommandResult.NO_ACK ? 5 : 1))
    }

    /** What an ArduPilot vehicle does when it accepts the command. */
    void effect(Command c) {
        float[] p = c.params
        switch (c.command) {
            case MAV_CMD.MAV_CMD_DO_SET_MODE: heartbeat(state.armed(), requestedMode(p)); break
            case MAV_CMD.MAV_CMD_COMPONENT_ARM_DISARM: heartbeat(p[0] == 1f, state.modeName()); break
            case MAV_CMD.MAV_CMD_DO_SET_HOME: state = state.withHome(Position.fromDegrees(p[4], p[5], p[6])); break
            case MAV_CMD.MAV_CMD_DO_SET_MISSION_CURRENT: missionCurrent(state.autopilot().missionSeq(p[0] as int), state.missionState()); break
            case MAV_CMD.MAV_CMD_MISSION_START: missionCurrent(Math.max(1, state.missionSeq()), MISSION_STATE.MISSION_STATE_ACTIVE); break
            default: break
        }
    }

    /** The mode DO_SET_MODE asks for, by the autopilot's way of asking. */
    String requestedMode(float[] p) {
        long custom = state.autopilot() == Autopilot.PX4 ? Px4Modes.customMode(p[1] as int, p[2] as int) : p[1] as long
        state.modes().name(custom)
    }

    /** "DO_SET_MODE GUIDED", "ARM", "DO_SET_HOME 40.444233 -7.375234 820.0", "DO_SET_MISSION_CURRENT 1", "MISSION_START". */
    String describe(int command, float[] p) {
        switch (command) {
            case MAV_CMD.MAV_CMD_DO_SET_MODE: return "DO_SET_MODE ${requestedMode(p)}"
            case MAV_CMD.MAV_CMD_COMPONENT_ARM_DISARM: return p[0] == 1f ? 'ARM' : 'DISARM'
            case MAV_CMD.MAV_CMD_DO_SET_HOME: return "DO_SET_HOME ${p[4]} ${p[5]} ${p[6]}"
            case MAV_CMD.MAV_CMD_DO_SET_MISSION_CURRENT: return "DO_SET_MISSION_CURRENT ${p[0] as int}"
            case MAV_CMD.MAV_CMD_DO_FENCE_ENABLE: return "DO_FENCE_ENABLE ${p[0] as int}"
            case MAV_CMD.MAV_CMD_DO_AUX_FUNCTION: return "DO_AUX_FUNCTION ${p[0] as int} ${p[1] as int}"
            default: return new CommandResult(command, 0, 0).commandName()
        }
    }

    // ---- answering transfers

    /** The oldest transfer not ended yet. */
    Transfer pendingTransfer() {
        def t = transfers.find { !it.result.done }
        assert t != null: "no transfer waits; asked for: ${transfers}"
        t
    }

    /** Whether a PX4 vehicle finds an uploaded mission feasible, and says so in MISSION_CURRENT (NOT_STARTED). */
    boolean feasible = true
    /**
     * The id the next mission upload gives (MISSION_ACK.opaque_id), 0 none; with one, MISSION_CURRENT names the
     * mission at once ({@link #missionId}) with no current item and its earlier state until {@link #checked}.
     */
    long uploadId = 0
    /** The mission id MISSION_CURRENT names, 0 none. */
    long missionId = 0

    /** The oldest waiting upload succeeds: the vehicle holds its items; a PX4 vehicle checks a mission then. */
    void completeUpload(Transfer t = pendingTransfer()) {
        assert t.upload
        stored[t.type] = t.items
        boolean mission = t.type == MissionType.MISSION
        t.result.complete(new TransferResult(true, null, t.items, 0, 0, false, '', mission ? uploadId : 0))
        if (mission && state.autopilot() == Autopilot.PX4) {
            if (uploadId == 0) {
                checked()
            } else if (uploadId != missionId) {
                missionId = uploadId
                uncheckedCurrent()
            }
        }
    }

    /** PX4's verdict on the mission it holds, in MISSION_CURRENT: NOT_STARTED at its first item, or NO_MISSION. */
    void checked() {
        missionCurrent(1, feasible ? MISSION_STATE.MISSION_STATE_NOT_STARTED : MISSION_STATE.MISSION_STATE_NO_MISSION)
    }

    /** MISSION_CURRENT of a PX4 vehicle that took a new mission its navigator has not checked: no current item, the earlier state. */
    void uncheckedCurrent() {
        int total = (stored[MissionType.MISSION]?.size() ?: 1) - 1
        state = state.withMissionCurrent(65535, total, state.missionState(), missionId)
        def m = new msg_mission_current()
        m.seq = 65535
        m.total = total
        m.mission_state = (short) state.missionState()
        m.mission_id = missionId
        current?.consume(m)
    }

    /** The oldest waiting transfer fails with the error. */
    void failTransfer(String error, Transfer t = pendingTransfer()) {
        t.result.complete(new TransferResult(false, error, [], 0, 0))
    }

    /**
     * The oldest waiting download returns what the vehicle holds (or the given items): a mission's
     * item 0 is the vehicle's home, as ArduPilot sends it.
     */
    void completeDownload(Transfer t = pendingTransfer(), List<MissionItem> items = null) {
        assert !t.upload
        List<MissionItem> back = items ?: stored[t.type] ?: []
        if (items == null && t.type == MissionType.MISSION && !back.empty && state.home() != null) {
            back = [MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, state.home(), 0, 0, 0, 0)] + back.drop(1)
        }
        t.result.complete(new TransferResult(true, null, back, 0, 0))
    }

    // ---- telemetry the spec sets

    /** A HEARTBEAT: armed or not, in a mode of the family. */
    void heartbeat(boolean armed, String mode) {
        def hb = new msg_heartbeat()
        hb.base_mode = (short) ((armed ? 128 : 0) | 1)
        hb.custom_mode = state.modes().number(mode).asLong
        state = state.withHeartbeat(hb, clock.nanoTime())
    }

    void mode(String mode) { heartbeat(state.armed(), mode) }

    void armed(boolean armed) { heartbeat(armed, state.modeName()) }

    /** SYS_STATUS with its pre-arm check sensor passing or failing. */
    void prearm(boolean passing) {
        def s = new msg_sys_status()
        s.onboard_control_sensors_present = PREARM
        s.onboard_control_sensors_enabled = PREARM
        s.onboard_control_sensors_health = passing ? PREARM : 0
        state = state.withSystemStatus(s, clock.nanoTime())
    }

    /** Ready for a mission: a position at home, its home, pre-arm checks passing. */
    void ready() {
        at(0, 0)
        state = state.withHome(HOME)
        prearm(true)
    }

    /** GLOBAL_POSITION_INT: north of home and up, in metres. */
    void at(double north, double up) {
        state = state.withPosition(HOME.displace(north, 0, -up), up, Double.NaN, clock.nanoTime())
    }

    /** STATUSTEXT, into the state and to the executor flying on the vehicle (as MissionService routes it). */
    void text(String line, int severity = MAV_SEVERITY.MAV_SEVERITY_INFO) {
        state = state.withStatusText(line)
        def m = new msg_statustext()
        m.severity = (short) severity
        m.setText(line)
        current?.consume(m)
    }

    void landedState(int landed) { state = state.withExtendedState(landed, 0) }

    /** MISSION_CURRENT of item {@code seq} as the runtime numbers items (home 0), sent as the autopilot numbers them. */
    void missionCurrent(int seq, int missionState = MISSION_STATE.MISSION_STATE_ACTIVE) {
        int total = (stored[MissionType.MISSION]?.size() ?: 1) - 1
        int sent = state.autopilot().vehicleSeq(seq)
        state = state.withMissionCurrent(sent, total, missionState, missionId)
        def m = new msg_mission_current()
        m.seq = sent
        m.total = total
        m.mission_state = (short) missionState
        m.mission_id = missionId
        current?.consume(m)
    }

    /** MISSION_ITEM_REACHED, to the executor flying on the vehicle (as MissionService routes it), numbered as the autopilot does. */
    void reached(int seq) {
        def m = new msg_mission_item_reached()
        m.seq = state.autopilot().vehicleSeq(seq)
        current?.consume(m)
    }

    /** Flies on: item {@code seq - 1} reached, item {@code seq} current. */
    void next(int seq) {
        reached(seq - 1)
        missionCurrent(seq)
    }

    /** Lands and disarms, as ArduCopter at the end of a LAND: on the ground, disarmed. */
    void landAndDisarm() {
        at(state.position() == null ? 0 : HOME.displacementTo(state.position())[0], 0)
        landedState(MAV_LANDED_STATE.MAV_LANDED_STATE_ON_GROUND)
        armed(false)
    }

    /** The commands sent, as "time text" lines. */
    List<String> commandLines() { commands*.toString() }
}
