package dolphin.mission.flight;

import dolphin.mission.model.DroneCommand;
import dolphin.mission.model.HeightCheck;
import dolphin.mission.model.JumpToItem;
import dolphin.mission.model.Mission;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import dolphin.mission.transfer.MissionVerification;
import dolphin.mission.transfer.TransferResult;
import com.MAVLink.common.msg_mission_item_reached;
import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_MODE_FLAG;
import com.MAVLink.enums.MAV_RESULT;
import com.MAVLink.enums.MISSION_STATE;
import dolphin.core.CompletionState;
import dolphin.core.Node;
import dolphin.core.Position;
import dolphin.core.PlatformTaskExecutor;
import dolphin.mavlink.CommandResult;
import dolphin.mavlink.MAVLinkCommunications;
import dolphin.mavlink.MAVLinkNode;
import dolphin.mavlink.VehicleFamily;
import dolphin.mavlink.VehicleState;
import java.time.Duration;
import java.util.ArrayDeque;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.OptionalLong;
import java.util.TreeMap;
import java.util.concurrent.CompletableFuture;

/**
 * Flies a {@link Mission} on one vehicle (report Listing 8; design §6): a state machine stepped on
 * the script thread, PREPARE, UPLOAD, VERIFY, ARM, START, RUNNING, then DONE or ERROR, each state
 * with a deadline in clock time. Commands and transfers run on the communications thread; each
 * state waits for one of them, and their completion wakes the task tree.
 */
public final class MissionExecutor extends PlatformTaskExecutor {

    public enum State { PREPARE, UPLOAD, VERIFY, ARM, START, RUNNING, DONE, ERROR }

    private final Mission mission;
    private final Map<JumpToItem, Integer> jumpsLeft = new HashMap<>();
    private MAVLinkNode node;
    private MAVLinkCommunications comms;
    private MissionExecutorConfig config;
    private FlightRules rules;
    /** The commands of PREPARE and START. */
    private CommandSteps steps;
    private List<MissionItem> items;
    /** The lists still to upload and verify, in order (fence, rally points, mission); the first is in transfer. */
    private final ArrayDeque<Map.Entry<MissionType, List<MissionItem>>> lists = new ArrayDeque<>();
    private MissionEnd end;
    private TreeMap<Integer, List<DroneCommand>> keyed;
    private volatile State state = State.PREPARE;
    private String failure;
    private long deadline;
    private CompletableFuture<?> pending;
    private String uploadError;
    private long nextAttempt;
    private boolean armModeSet;
    private volatile int reached;
    private int sentUpTo;
    private int reported;
    private boolean active;
    /** Whether the vehicle has shown itself ready; until then PREPARE waits (Readiness). */
    private boolean ready;
    /** What the vehicle was last waiting for, shown once per change; null when it has not waited. */
    private String waitingFor;
    private long prepareStart;
    /** A jump sent and not yet seen on the vehicle (MISSION_CURRENT back at or before its item); null when none. */
    private JumpToItem jumping;
    private long resendJump;

    public MissionExecutor(Mission mission) {
        super(mission);
        this.mission = mission;
    }

    public State state() {
        return state;
    }

    /** The report's consume(MISSION_ITEM_REACHED), on the communications thread: "reached at least seq". */
    public void consume(msg_mission_item_reached message) {
        synchronized (this) {
            // Until the vehicle shows it jumped, a MISSION_ITEM_REACHED may be from before the jump.
            if (jumping == null) {
                reached = Math.max(reached, message.seq);
            }
        }
    }

    @Override
    protected void onStart() {
        Node vehicle = getVehicle();
        if (!(vehicle instanceof MAVLinkNode n)) {
            failure = "vehicle " + vehicle.getId() + " is not a MAVLink vehicle";
            return;
        }
        node = n;
        comms = node.communications();
        config = comms.missionExecutorConfig();
        rules = FlightRules.of(node.getFamily());
        steps = new CommandSteps(node.getId(), node::state, config.retry(), this::waitFor, this::watch);
        node.setExecutor(this);
        keyed = new TreeMap<>(mission.nonMissionCommands());
        keyed.values().forEach(cmds -> cmds.stream().filter(c -> c instanceof JumpToItem)
                .forEach(c -> jumpsLeft.put((JumpToItem) c, ((JumpToItem) c).repetitions())));
        prepareStart = clock().nanoTime();
        enter(State.PREPARE, config.prepare());
    }

    @Override
    protected CompletionState onStep() {
        if (failure != null) {
            return fail(failure);
        }
        long now = clock().nanoTime();
        if (state != State.RUNNING && now > deadline) {
            return fail(state == State.PREPARE ? notReady() : state + " did not finish within its deadline");
        }
        return switch (state) {
            case PREPARE -> prepare(now);
            case UPLOAD -> upload();
            case VERIFY -> verify();
            case ARM -> arm(now);
            case START -> {
                if (steps.run(now)) {
                    progress("started");
                    enter(State.RUNNING, Duration.ZERO);
                }
                yield steps.failure() != null ? fail(steps.failure()) : CompletionState.IN_PROGRESS;
            }
            case RUNNING -> running();
            case DONE -> CompletionState.DONE;
            case ERROR -> fail(failure);
        };
    }

    /**
     * Waits until the vehicle is ready (Readiness), then holds it if it is flying another mission,
     * sets the mission's home, checks the heights against home, and starts the upload. A vehicle
     * that refuses DO_SET_HOME for now (FAILED: no position estimate yet) is asked again.
     */
    private CompletionState prepare(long now) {
        if (!ready) {
            var missing = Readiness.missing(node.state(), mission.getHome() == null);
            if (missing.isPresent()) {
                waitFor(missing.get());
                return CompletionState.IN_PROGRESS;
            }
            ready = true;
            queuePreparation();
        }
        if (!steps.run(now)) {
            return steps.failure() != null ? fail(steps.failure()) : CompletionState.IN_PROGRESS;
        }
        try {
            items = mission.items(node.getHome());
            Position home = mission.getHome() != null ? mission.getHome() : node.getHome();
            var low = HeightCheck.firstTooLow(mission, home);
            if (low.isPresent()) {
                return fail(low.get().message());
            }
        } catch (RuntimeException e) {
            return fail(e.getMessage());
        }
        end = new MissionEnd(rules, items, node.getId(), config.modeGrace(), config.landingStall());
        List<DroneCommand> beforeUpload = keyed.remove(0);
        if (beforeUpload != null) {
            beforeUpload.forEach(c -> c.toMavLinkMessage(node).forEach(node::send));
        }
        if (waitingFor != null) {
            progress("vehicle ready after " + (now - prepareStart) / 1_000_000_000L + " s");
        }
        if (!mission.fence().isEmpty()) {
            lists.add(Map.entry(MissionType.FENCE, mission.fence().items()));
        }
        if (!mission.rally().isEmpty()) {
            lists.add(Map.entry(MissionType.RALLY, mission.rally().items()));
        }
        lists.add(Map.entry(MissionType.MISSION, items));
        startUpload();
        return CompletionState.IN_PROGRESS;
    }

    /** Uploads the next list: the fence and rally points go before the mission (docs/airspace.md). */
    private void startUpload() {
        var next = lists.peek();
        uploadError = null;
        progress("uploading " + (next.getKey() == MissionType.MISSION ? "" : "the " + next.getKey().label() + ": ")
                + next.getValue().size() + (next.getValue().size() == 1 ? " item" : " items"));
        pending = watch(node.getUploadProtocol().upload(next.getKey(), next.getValue()));
        enter(State.UPLOAD, config.upload());
    }

    private void queuePreparation() {
        VehicleState s = node.state();
        if (s.armed() && isMode(s, "AUTO")) {
            String hold = rules.holdMode();
            steps.add(new CommandSteps.Step("leaving AUTO for " + hold + " before the new mission", () -> setMode(hold), st -> isMode(st, hold)));
        }
        if (mission.getHome() != null) {
            var h = mission.getHome();
            steps.add(new CommandSteps.Step("DO_SET_HOME", () -> comms.command(node, MAV_CMD.MAV_CMD_DO_SET_HOME, 0, 0, 0, 0,
                    (float) h.latitudeDegrees(), (float) h.longitudeDegrees(), (float) h.hae()),
                    st -> st.home() != null && st.home().distanceTo(h) < 1, true));
        }
    }

    /** Says what the vehicle is waiting for, once per change. */
    private void waitFor(String what) {
        if (!what.equals(waitingFor)) {
            waitingFor = what;
            context().listener().message("waiting for vehicle " + node.getId() + ": " + what);
        }
    }

    /** PREPARE's deadline passed: what the vehicle was waiting for, in its own words when it said any. */
    private String notReady() {
        String why = Readiness.prearmText(node.state()).orElse(waitingFor != null ? waitingFor : "not ready");
        return "vehicle " + node.getId() + " was not ready within " + config.prepare().toSeconds() + " s: " + why;
    }

    private CompletionState upload() {
        TransferResult r = done();
        if (r == null) {
            return CompletionState.IN_PROGRESS;
        }
        if (!r.success()) {
            if (!config.verify()) {
                return fail(r.error());
            }
            // The vehicle may hold the mission although the final ACK was lost: the download decides.
            uploadError = r.error();
        }
        if (config.verify()) {
            pending = watch(node.getDownloadProtocol().download(lists.peek().getKey()));
            enter(State.VERIFY, config.upload());
        } else {
            nextList();
        }
        return CompletionState.IN_PROGRESS;
    }

    /** The list in transfer is done: the next one, or ARM after the mission. */
    private void nextList() {
        lists.poll();
        if (lists.isEmpty()) {
            enterArm();
        } else {
            startUpload();
        }
    }

    private CompletionState verify() {
        TransferResult r = done();
        if (r == null) {
            return CompletionState.IN_PROGRESS;
        }
        if (!r.success()) {
            return fail(uploadError != null ? uploadError : "verifying the upload failed: " + r.error());
        }
        MissionType type = lists.peek().getKey();
        var difference = MissionVerification.firstDifference(type, lists.peek().getValue(), r.items());
        if (difference.isPresent()) {
            return fail(uploadError != null ? uploadError
                    : "the vehicle holds another " + type.label() + " than the one uploaded: " + difference.get());
        }
        String what = type == MissionType.MISSION ? "upload" : type.label();
        progress(uploadError == null ? what + " verified" : what + " verified by download (" + uploadError + ")");
        nextList();
        return CompletionState.IN_PROGRESS;
    }

    private void enterArm() {
        enter(State.ARM, config.arm());
        nextAttempt = clock().nanoTime();
    }

    /** In the family's arming mode, if it has one, then arm; arming is retried until the deadline. */
    private CompletionState arm(long now) {
        var armMode = rules.armMode();
        if (armMode.isPresent() && !armModeSet) {
            String mode = armMode.get();
            if (pending == null) {
                pending = watch(setMode(mode));
            }
            CommandResult r = commandDone();
            if (r == null) {
                return CompletionState.IN_PROGRESS;
            }
            if (!steps.tookEffect(r, st -> isMode(st, mode))) {
                return fail(steps.refusal(mode, r));
            }
            armModeSet = true;
        }
        if (pending == null) {
            if (now < nextAttempt) {
                return CompletionState.IN_PROGRESS;
            }
            pending = watch(comms.command(node, MAV_CMD.MAV_CMD_COMPONENT_ARM_DISARM, 1));
        }
        CommandResult r = commandDone();
        if (r == null) {
            return CompletionState.IN_PROGRESS;
        }
        if (steps.tookEffect(r, VehicleState::armed)) {
            progress("armed");
            // From the first item, whatever the vehicle ran before: ArduPilot keeps its mission's current item
            // across an upload, and a copter on the ground refuses AUTO unless that item leads to a take-off.
            if (mission.fenceEnabled()) {
                steps.add(new CommandSteps.Step("MAV_CMD_DO_FENCE_ENABLE 1", () -> comms.command(node,
                        MAV_CMD.MAV_CMD_DO_FENCE_ENABLE, 1, 0), st -> false));
            }
            steps.add(new CommandSteps.Step("MAV_CMD_DO_SET_MISSION_CURRENT 1", () -> comms.command(node,
                    MAV_CMD.MAV_CMD_DO_SET_MISSION_CURRENT, 1, 1), st -> st.missionSeq() == 1));
            steps.add(new CommandSteps.Step("AUTO", () -> setMode("AUTO"), st -> isMode(st, "AUTO")));
            if (rules.needsMissionStart()) {
                steps.add(new CommandSteps.Step("MAV_CMD_MISSION_START", () -> comms.command(node, MAV_CMD.MAV_CMD_MISSION_START, 0, 0),
                        st -> st.missionState() == MISSION_STATE.MISSION_STATE_ACTIVE));
            }
            enter(State.START, config.start());
            return CompletionState.IN_PROGRESS;
        }
        if (now + config.retry().toNanos() > deadline) {
            return fail("vehicle " + node.getId() + " refused to arm for " + config.arm().toSeconds() + " s: "
                    + lastArmText(r));
        }
        nextAttempt = now + config.retry().toNanos();
        return CompletionState.IN_PROGRESS;
    }

    private String lastArmText(CommandResult r) {
        List<String> texts = node.state().statusTexts();
        for (int i = texts.size() - 1; i >= 0; i--) {
            if (texts.get(i).contains("Arm")) {
                return texts.get(i);
            }
        }
        return r.resultName();
    }

    private CompletionState running() {
        VehicleState s = node.state();
        if (s.missionState() == MISSION_STATE.MISSION_STATE_ACTIVE) {
            active = true;
        }
        int last = items.size() - 1;
        if (!jumpSeen(s)) {
            return CompletionState.IN_PROGRESS;
        }
        int r = reached;
        if (active && s.missionState() == MISSION_STATE.MISSION_STATE_ACTIVE) {
            r = Math.max(r, s.missionSeq() - 1);
        }
        if (r > reported) {
            reported = r;
            progress("item " + Math.min(r, last) + " of " + last + " reached");
        }
        sendKeyedCommands(r);
        MissionEnd.Verdict verdict = end.judge(s, r, isMode(s, "AUTO"), clock().nanoTime());
        if (verdict.done()) {
            return finish();
        }
        return verdict.error() != null ? fail(verdict.error()) : CompletionState.IN_PROGRESS;
    }

    /**
     * After a jump, MISSION_CURRENT and MISSION_ITEM_REACHED from before it (items past the jump's key)
     * still arrive: they are ignored until MISSION_CURRENT is back at or before the jump's item. The jump's
     * MISSION_SET_CURRENT is sent again each second until then, in case it was lost.
     */
    private boolean jumpSeen(VehicleState s) {
        synchronized (this) {
            if (jumping == null) {
                return true;
            }
            if (s.missionState() == MISSION_STATE.MISSION_STATE_ACTIVE && s.missionSeq() >= 0 && s.missionSeq() <= jumping.item()) {
                jumping = null;
                return true;
            }
        }
        long now = clock().nanoTime();
        if (now >= resendJump) {
            jumping.toMavLinkMessage(node).forEach(node::send);
            resendJump = now + Duration.ofSeconds(1).toNanos();
        }
        return false;
    }

    /** Sends the non-mission commands keyed by the items reached; a jump goes back and runs them again. */
    private void sendKeyedCommands(int r) {
        if (r <= sentUpTo) {
            return;
        }
        for (Map.Entry<Integer, List<DroneCommand>> e : keyed.subMap(sentUpTo, false, r, true).entrySet()) {
            for (DroneCommand c : e.getValue()) {
                if (c instanceof JumpToItem jump) {
                    int left = jumpsLeft.getOrDefault(jump, 0);
                    if (left > 0) {
                        jumpsLeft.put(jump, left - 1);
                        jump.toMavLinkMessage(node).forEach(node::send);
                        progress("jump to item " + jump.item());
                        synchronized (this) {
                            reached = jump.item() - 1;
                            jumping = jump;
                        }
                        resendJump = clock().nanoTime() + Duration.ofSeconds(1).toNanos();
                        sentUpTo = jump.item() - 1;
                        reported = sentUpTo;
                        return;
                    }
                } else {
                    c.toMavLinkMessage(node).forEach(node::send);
                }
            }
            sentUpTo = e.getKey();
        }
    }

    private CompletionState finish() {
        state = State.DONE;
        progress("done");
        return CompletionState.DONE;
    }

    private CompletableFuture<CommandResult> setMode(String name) {
        OptionalLong mode = getFamily().modeNumber(name);
        if (mode.isEmpty()) {
            return CompletableFuture.completedFuture(new CommandResult(MAV_CMD.MAV_CMD_DO_SET_MODE, MAV_RESULT.MAV_RESULT_UNSUPPORTED, 0));
        }
        return comms.command(node, MAV_CMD.MAV_CMD_DO_SET_MODE, MAV_MODE_FLAG.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED, mode.getAsLong());
    }

    private VehicleFamily getFamily() {
        return node.getFamily();
    }

    private static boolean isMode(VehicleState s, String name) {
        return s.heartbeat() != null && s.family().modeNumber(name).orElse(-1) == s.customMode();
    }

    private CommandResult commandDone() {
        return (CommandResult) done();
    }

    @SuppressWarnings("unchecked")
    private <T> T done() {
        if (pending == null || !pending.isDone()) {
            return null;
        }
        T r = (T) pending.join();
        pending = null;
        return r;
    }

    private void enter(State next, Duration limit) {
        state = next;
        deadline = clock().nanoTime() + limit.toNanos();
    }

    /** Steps the task tree as soon as the operation completes, not at the next tick. */
    private <T> CompletableFuture<T> watch(CompletableFuture<T> operation) {
        operation.whenComplete((r, e) -> comms.wakeScript());
        return operation;
    }

    private CompletionState fail(String why) {
        failure = why;
        state = State.ERROR;
        return CompletionState.error("mission " + mission.getId() + (node != null ? " on vehicle " + node.getId() : "") + ": " + why);
    }

    private void progress(String what) {
        context().listener().message("mission " + mission.getId() + " on vehicle " + node.getId() + ": " + what);
    }

    /** Cut short (a condition, a stopped sequence): the vehicle is sent home if it may be flying. */
    @Override
    protected void onStop() {
        if (node != null && (state == State.ARM || state == State.START || state == State.RUNNING)) {
            comms.command(node, MAV_CMD.MAV_CMD_DO_SET_MODE, MAV_MODE_FLAG.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED,
                    getFamily().modeNumber("RTL").orElse(0));
            progress("cut short: RTL");
        }
        release();
    }

    @Override
    protected void onCompletion() {
        release();
    }

    private void release() {
        if (node != null && node.getExecutor() == this) {
            node.setExecutor(null);
        }
    }
}
