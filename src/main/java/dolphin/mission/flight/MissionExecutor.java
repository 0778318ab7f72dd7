package dolphin.mission.flight;

import com.MAVLink.common.msg_mission_current;
import com.MAVLink.common.msg_mission_item_reached;
import com.MAVLink.common.msg_statustext;
import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_RESULT;
import com.MAVLink.enums.MISSION_STATE;
import dolphin.core.CompletionState;
import dolphin.core.Node;
import dolphin.core.PlatformTaskExecutor;
import dolphin.core.Position;
import dolphin.core.VehicleEvent.EventKind;
import dolphin.mavlink.CommandResult;
import dolphin.mavlink.EnumNames;
import dolphin.mavlink.StatusText;
import dolphin.mavlink.Autopilot;
import dolphin.mavlink.VehicleState;
import dolphin.mission.model.DroneCommand;
import dolphin.mission.model.FlightWay;
import dolphin.mission.model.HeightCheck;
import dolphin.mission.model.JumpToItem;
import dolphin.mission.model.Mission;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import dolphin.mission.survey.PolygonSurvey;
import dolphin.mission.transfer.MissionVerification;
import dolphin.mission.transfer.TransferResult;
import java.time.Duration;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.OptionalLong;
import java.util.TreeMap;
import java.util.concurrent.CompletableFuture;
import java.util.function.Function;

/**
 * Flies a {@link Mission} on one vehicle: a state machine stepped on the script thread, PREPARE,
 * UPLOAD, VERIFY (each list: fence, rally points, mission), ARM, START, RUNNING, then DONE or ERROR
 * (docs/decisions.md, "The mission executor"). Each state is an object that owns its data and its
 * deadline in clock time; it waits for one command or transfer at a time, whose completion wakes
 * the task tree. The vehicle is reached through {@link MissionVehicle} only.
 */
public final class MissionExecutor extends PlatformTaskExecutor {

    public enum FlightState { PREPARE, UPLOAD, VERIFY, ARM, START, RUNNING, DONE, ERROR }

    private static final Duration JUMP_RESEND = Duration.ofSeconds(1);
    /** How long an ArduPlane's first EXTENDED_SYS_STATE is awaited: its stream is asked for at 0.5 Hz at least. */
    private static final Duration VTOL_STATE_WAIT = Duration.ofSeconds(5);
    /** How long a vehicle that checks a mission after its upload is given to find it feasible (PX4 SITL: well under a second). */
    private static final Duration MISSION_CHECK_WAIT = Duration.ofSeconds(10);
    /** How often a long upload says how far it is, in clock time (a lossy link can make it last a minute). */
    private static final long TRANSFER_REPORT_NANOS = 5_000_000_000L;

    private final Mission mission;
    private final Function<Node, MissionVehicle> vehicles;
    /** MISSION_ITEM_REACHED heard since the start, written on the communications thread. */
    private final ItemsReached reached = new ItemsReached();
    /** What the vehicle says of its items, in order, once the plan is made; fed on the communications thread. */
    private volatile ItemRefusals refusals;
    /** What the vehicle said and when, for the errors of a flight that goes wrong; fed on the communications thread. */
    private final VehicleWords words = new VehicleWords();
    private MissionVehicle vehicle;
    private MissionExecutorConfig config;
    private FlightRules rules;
    private Stage stage;
    private volatile FlightState state = FlightState.PREPARE;
    /** When the mission's upload began: a vehicle that checks the mission may refuse it from then on. */
    private long missionUploadBegan;
    /** The vehicle's verdict on the mission in its latest upload, watched from the upload's beginning; fed on the communications thread. */
    private volatile FeasibilityWatch feasibility;
    private String failure;

    /** @param vehicles the mission side of the vehicle the executor is given; null when it has none */
    public MissionExecutor(MissionTask task, Function<Node, MissionVehicle> vehicles) {
        super(task);
        this.mission = task.mission();
        this.vehicles = vehicles;
    }

    public FlightState state() {
        return state;
    }

    public Mission mission() {
        return mission;
    }

    /**
     * MISSION_ITEM_REACHED, on the communications thread: "reached at least seq". From an autopilot that
     * repeats it (PX4: ten more times, a second apart), one past the vehicle's current item is an earlier
     * mission's, still repeated as this one starts.
     */
    public void consume(msg_mission_item_reached message) {
        int seq = autopilot().missionSeq(message.seq);
        if (autopilot().repeatsItemReached() && seq > vehicle.state().missionSeq()) {
            return;
        }
        reached.reached(seq);
        ItemRefusals r = refusals;
        if (r != null) {
            r.reached(seq);
        }
    }

    /** MISSION_CURRENT, on the communications thread, in the order the vehicle sent it. */
    public void consume(msg_mission_current message) {
        FeasibilityWatch f = feasibility;
        if (f != null) {
            f.heard(message.seq, message.total, message.mission_state, message.mission_id);
        }
        ItemRefusals r = refusals;
        if (r != null) {
            r.current(autopilot().missionSeq(message.seq), message.mission_state, clock().nanoTime());
        }
    }

    /** STATUSTEXT, on the communications thread, in the order the vehicle sent it. */
    public void consume(msg_statustext message) {
        long now = clock().nanoTime();
        String text = StatusText.of(message);
        words.heard(message.severity, text, now);
        ItemRefusals r = refusals;
        if (r != null) {
            r.text(message.severity, text, now);
        }
    }

    @Override
    protected void onStart() {
        Node node = getVehicle();
        vehicle = vehicles.apply(node);
        if (vehicle == null) {
            failure = "vehicle " + node.getId() + " is not a MAVLink vehicle";
            return;
        }
        config = vehicle.executorConfig().with(mission.limits());
        rules = FlightRules.of(vehicle.state());
        vehicle.flying(this);
        enter(new Preparing(clock().nanoTime()));
    }

    @Override
    protected CompletionState onStep() {
        if (failure != null) {
            return fail(failure);
        }
        if (state == FlightState.DONE) {
            return CompletionState.DONE;
        }
        long now = clock().nanoTime();
        if (state != FlightState.RUNNING && now > stage.deadline) {
            return fail(stage.overdue());
        }
        return stage.step(now);
    }

    /** Cut short (a condition, a stopped sequence): the vehicle is sent home if it may be flying. */
    @Override
    protected void onStop() {
        if (vehicle != null && (state == FlightState.ARM || state == FlightState.START || state == FlightState.RUNNING)) {
            String mode = rules.cutShortMode();
            setMode(mode);
            progress("cut short: " + mode);
            if (stage.triggersCamera()) {
                vehicle.command(MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST, 0, 0, 0);
                progress("camera triggering by distance stopped");
            }
        }
        landed();
    }

    @Override
    protected void onCompletion() {
        landed();
    }

    private void landed() {
        if (vehicle != null) {
            vehicle.landed(this);
        }
    }

    private void enter(Stage next) {
        stage = next;
        state = next.state;
    }

    /** One state of the flight: its data and its deadline. */
    private abstract class Stage {
        final FlightState state;
        final long deadline;

        Stage(FlightState state, Duration limit) {
            this.state = state;
            this.deadline = clock().nanoTime() + limit.toNanos();
        }

        abstract CompletionState step(long now);

        /** Whether the mission this stage flies sets a camera trigger distance; none before it is planned. */
        boolean triggersCamera() {
            return false;
        }

        /** Why the flight fails when the deadline passes. */
        String overdue() {
            return state + " did not finish within its deadline";
        }
    }

    /** What the flight follows once uploaded: the items, how its end is judged, and the ground-side commands by item. */
    private record Plan(List<MissionItem> items, MissionEnd end, TreeMap<Integer, List<DroneCommand>> keyed) {

        /**
         * Whether the items set a camera trigger distance: ArduPilot keeps triggering by distance in any mode
         * until a distance of 0 is set (docs/decisions.md, "Camera triggers on ArduPilot").
         */
        boolean triggersCamera() {
            return items.stream().anyMatch(i -> i.command() == MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST && i.param1() > 0);
        }
    }

    /**
     * Waits until the vehicle is ready (Readiness), then holds it if it is flying another mission,
     * sets the mission's home, checks the heights against home, and starts the upload. A vehicle
     * that refuses DO_SET_HOME for now (FAILED: no position estimate yet) is asked again.
     */
    private final class Preparing extends Stage {
        private final long since;
        private final CommandSteps steps;
        /**
         * The family's commands to a disarmed vehicle before it can pass its pre-arm checks, once it has a
         * position estimate: sent at boot, ArduCopter's first read of its RC inputs undid a helicopter's
         * interlock switched off (SITL, started with the script).
         */
        private final CommandSteps grounded;
        private boolean ready;
        /** The vehicle's parameters its family needs, once asked; each read completes empty when unanswered. */
        private Map<String, CompletableFuture<OptionalDouble>> parameters;
        /** What the vehicle was last waiting for, shown once per change; null when it has not waited. */
        private String waitingFor;

        Preparing(long now) {
            super(FlightState.PREPARE, config.prepare());
            since = now;
            steps = commandSteps(this::waitFor);
            grounded = commandSteps(this::waitFor);
            if (!vehicle.state().armed()) {
                rules.onTheGround().forEach(c -> grounded.add(familyStep(c)));
            }
        }

        @Override
        CompletionState step(long now) {
            if (!ready) {
                var unlocated = Readiness.unlocated(vehicle.state(), mission.getHome() == null);
                if (unlocated.isPresent()) {
                    waitFor(unlocated.get());
                    return CompletionState.IN_PROGRESS;
                }
                if (!grounded.run(now)) {
                    return grounded.failure() != null ? fail(grounded.failure()) : CompletionState.IN_PROGRESS;
                }
                var missing = Readiness.missing(vehicle.state(), mission.getHome() == null);
                if (missing.isPresent()) {
                    waitFor(missing.get());
                    return CompletionState.IN_PROGRESS;
                }
                if (vtolStateUnheard(vehicle.state(), now)) {
                    waitFor("its EXTENDED_SYS_STATE, which tells a QuadPlane from a plane");
                    return CompletionState.IN_PROGRESS;
                }
                ready = true;
                rules = FlightRules.of(vehicle.state());
                hold();
                parameters = new LinkedHashMap<>();
                rules.parameters().forEach(name -> parameters.put(name, watch(vehicle.parameter(name))));
            }
            if (!steps.run(now)) {
                return steps.failure() != null ? fail(steps.failure()) : CompletionState.IN_PROGRESS;
            }
            if (!parameters.values().stream().allMatch(CompletableFuture::isDone)) {
                waitFor("its parameters " + String.join(", ", parameters.keySet()));
                return CompletionState.IN_PROGRESS;
            }
            Boarded boarded;
            try {
                Position vehicleHome = vehicle.state().home();
                var unsafe = HeightCheck.firstUnsafe(mission, mission.getHome() != null ? mission.getHome() : vehicleHome);
                if (unsafe.isPresent()) {
                    return fail(unsafe.get().message());
                }
                Optional<String> wrongVehicle = wrongVehicle();
                if (wrongVehicle.isPresent()) {
                    return fail(wrongVehicle.get());
                }
                List<MissionItem> written = mission.items(vehicleHome);
                Map<Integer, FlightWay> ways = mission.ways();
                Optional<String> wrongWay = wrongWay(written, ways);
                if (wrongWay.isPresent()) {
                    return fail(wrongWay.get());
                }
                Map<String, OptionalDouble> values = new LinkedHashMap<>();
                parameters.forEach((name, value) -> values.put(name, value.join()));
                boarded = rules.onBoard(written, new Boarding(mission.underwater().orElse(null), ways, values));
            } catch (RuntimeException e) {
                return fail("vehicle " + vehicle.vehicleId() + " (" + vehicle.state().kind() + ") cannot fly the mission: "
                        + e.getMessage());
            }
            List<MissionItem> items = boarded.items();
            for (int seq : boarded.added()) {
                var breached = mission.fence().breachedBy(items.get(seq).position());
                if (breached.isPresent()) {
                    return fail("item " + seq + ", the approach waypoint the landing after it needs, is outside the mission's fence ("
                            + breached.get().describe() + "): write the approach in the mission (docs/vtol.md)");
                }
            }
            for (MissionItem item : items) {
                var why = rules.cannotFly(item);
                if (why.isPresent()) {
                    return fail("item " + item.seq() + " (" + item.commandName() + ") cannot be flown by vehicle "
                            + vehicle.vehicleId() + " (" + vehicle.state().kind() + "): " + why.get());
                }
            }
            TreeMap<Integer, List<DroneCommand>> keyed = new TreeMap<>();
            mission.nonMissionCommands().forEach((seq, commands) -> keyed.put(boarded.seqOf(seq), commands));
            if (!boarded.added().isEmpty() && keyed.values().stream().flatMap(List::stream).anyMatch(c -> c instanceof JumpToItem)) {
                return fail("the mission jumps, and an approach waypoint was added before its landing: write the approach"
                        + " waypoint in the mission (docs/vtol.md)");
            }
            List<DroneCommand> beforeUpload = keyed.remove(0);
            if (beforeUpload != null) {
                beforeUpload.forEach(MissionExecutor.this::send);
            }
            if (waitingFor != null) {
                progress("vehicle ready after " + (now - since) / 1_000_000_000L + " s");
            }
            for (int seq : boarded.added()) {
                progress("item " + seq + " added: " + items.get(seq).commandName() + ", the approach to the landing after it");
            }
            Deque<Map.Entry<MissionType, List<MissionItem>>> lists = new ArrayDeque<>();
            if (!mission.fence().isEmpty()) {
                lists.add(Map.entry(MissionType.FENCE, mission.fence().items()));
            }
            if (!mission.rally().isEmpty()) {
                lists.add(Map.entry(MissionType.RALLY, mission.rally().items()));
            }
            lists.add(Map.entry(MissionType.MISSION, items));
            refusals = new ItemRefusals(rules, items, vehicle.vehicleId());
            enter(new Uploading(lists, new Plan(items, new MissionEnd(rules, items, vehicle.vehicleId(), config.stallLimit()),
                    keyed)));
            return CompletionState.IN_PROGRESS;
        }

        /**
         * An ArduPlane that has sent no EXTENDED_SYS_STATE yet (landed state undefined) may be a QuadPlane:
         * it is given {@link #VTOL_STATE_WAIT} from the start for one, which the runtime asks for at discovery.
         */
        private boolean vtolStateUnheard(VehicleState s, long now) {
            return s.mayBeVtol() && now - since < VTOL_STATE_WAIT.toNanos();
        }

        private void hold() {
            VehicleState s = vehicle.state();
            if (s.armed() && s.inMode(rules.missionMode())) {
                String hold = rules.holdMode();
                steps.add(new CommandSteps.Step("leaving " + rules.missionMode() + " for " + hold + " before the new mission", () -> setMode(hold),
                        st -> st.inMode(hold)));
            }
            if (mission.getHome() != null) {
                var h = mission.getHome();
                steps.add(new CommandSteps.Step("DO_SET_HOME", () -> vehicle.command(MAV_CMD.MAV_CMD_DO_SET_HOME, 0, 0, 0, 0,
                        (float) h.latitudeDegrees(), (float) h.longitudeDegrees(), (float) h.hae()),
                        st -> st.home() != null && st.home().distanceTo(h) < 1, true));
            }
        }

        /** A take-off or landing the script says to fly in a way the vehicle does not (a plane that is no VTOL, vertically). */
        private Optional<String> wrongWay(List<MissionItem> items, Map<Integer, FlightWay> ways) {
            for (Map.Entry<Integer, FlightWay> e : ways.entrySet()) {
                if (!rules.flightWays().contains(e.getValue())) {
                    return Optional.of("item " + e.getKey() + " (" + items.get(e.getKey()).commandName() + ") is to be flown "
                            + e.getValue() + ", which vehicle " + vehicle.vehicleId() + " (" + vehicle.state().kind()
                            + ") does not do");
                }
            }
            return Optional.empty();
        }

        /**
         * An underwater mission on a vehicle that does not dive, or the other way round; a survey that
         * stops for its photos on one that cannot stop.
         */
        private Optional<String> wrongVehicle() {
            String v = "vehicle " + vehicle.vehicleId() + " (" + vehicle.state().kind() + ")";
            if (!rules.stops()) {
                for (DroneCommand c : mission.getCommandList()) {
                    if (c instanceof PolygonSurvey s && s.hoversToShoot()) {
                        return Optional.of(v + " cannot stop in the air to take its photos: the survey says"
                                + " hoverAndCapture(); leave it out, and the camera triggers by distance on the move");
                    }
                }
            }
            boolean underwater = mission.underwater().isPresent();
            if (underwater == rules.underwater()) {
                return Optional.empty();
            }
            return Optional.of(underwater ? "an underwater mission (maxDepth) for " + v + ", which does not dive"
                    : v + " goes under water: its mission must say how deep it may go, 'maxDepth METRES'"
                    + " (docs/underwater.md)");
        }

        /** Says what the vehicle is waiting for, once per change. */
        private void waitFor(String what) {
            if (!what.equals(waitingFor)) {
                waitingFor = what;
                context().listener().message("waiting for vehicle " + vehicle.vehicleId() + ": " + what);
            }
        }

        /** What the vehicle was waiting for, in its own words when it said any. */
        @Override
        String overdue() {
            String why = Readiness.prearmText(vehicle.state()).orElse(waitingFor != null ? waitingFor : "not ready");
            return "vehicle " + vehicle.vehicleId() + " was not ready within " + config.prepare().toSeconds() + " s: " + why;
        }
    }

    /** Uploads the first of the lists still to go: the fence and rally points before the mission (docs/airspace.md). */
    private final class Uploading extends Stage {
        private final Deque<Map.Entry<MissionType, List<MissionItem>>> lists;
        private final Plan plan;
        private final CompletableFuture<TransferResult> pending;
        private long lastReport = clock().nanoTime();

        Uploading(Deque<Map.Entry<MissionType, List<MissionItem>>> lists, Plan plan) {
            super(FlightState.UPLOAD, config.upload());
            this.lists = lists;
            this.plan = plan;
            var next = lists.peek();
            progress("uploading " + (next.getKey() == MissionType.MISSION ? "" : "the " + next.getKey().label() + ": ")
                    + next.getValue().size() + (next.getValue().size() == 1 ? " item" : " items"));
            if (next.getKey() == MissionType.MISSION) {
                missionUploadBegan = clock().nanoTime();
                feasibility = new FeasibilityWatch(plan.items().size() - 1, vehicle.state());
            }
            pending = watch(vehicle.upload(next.getKey(), next.getValue()));
        }

        @Override
        CompletionState step(long now) {
            if (!pending.isDone()) {
                if (now - lastReport >= TRANSFER_REPORT_NANOS) {
                    lastReport = now;
                    vehicle.transfer().ifPresent(status -> progress(status.text()));
                }
                return CompletionState.IN_PROGRESS;
            }
            TransferResult r = pending.join();
            if (!r.success() && !config.verify()) {
                return fail(r.error());
            }
            noteMissionId(lists.peek().getKey(), r);
            if (r.success() && r.verified()) {
                // the transfer read the list back itself (FTP, or a download that settled a lost ACK)
                MissionType type = lists.peek().getKey();
                progress((type == MissionType.MISSION ? "upload" : type.label()) + " verified"
                        + (r.note().isEmpty() ? "" : " (" + r.note() + ")"));
                nextList(lists, plan);
            } else if (config.verify()) {
                // The vehicle may hold the list although the final ACK was lost: the download decides.
                enter(new Verifying(lists, plan, r.success() ? null : r.error(), r.note()));
            } else {
                nextList(lists, plan);
            }
            return CompletionState.IN_PROGRESS;
        }
    }

    /** Downloads the list just uploaded and compares it with what was sent. */
    private final class Verifying extends Stage {
        private final Deque<Map.Entry<MissionType, List<MissionItem>>> lists;
        private final Plan plan;
        /** Why the upload failed, when it did: the download may still find the whole list on the vehicle. */
        private final String uploadError;
        /** How the upload went (e.g. item by item after FTP failed), for the verified line. */
        private final String uploadNote;
        private final CompletableFuture<TransferResult> pending;

        Verifying(Deque<Map.Entry<MissionType, List<MissionItem>>> lists, Plan plan, String uploadError, String uploadNote) {
            super(FlightState.VERIFY, config.upload());
            this.lists = lists;
            this.plan = plan;
            this.uploadError = uploadError;
            this.uploadNote = uploadNote;
            pending = watch(vehicle.download(lists.peek().getKey()));
        }

        @Override
        CompletionState step(long now) {
            if (!pending.isDone()) {
                return CompletionState.IN_PROGRESS;
            }
            TransferResult r = pending.join();
            if (!r.success()) {
                return fail(uploadError != null ? uploadError : "verifying the upload failed: " + r.error());
            }
            MissionType type = lists.peek().getKey();
            var difference = MissionVerification.firstDifference(autopilot(), type, lists.peek().getValue(), r.items());
            if (difference.isPresent()) {
                return fail(uploadError != null ? uploadError
                        : "the vehicle holds another " + type.label() + " than the one uploaded: " + difference.get());
            }
            noteMissionId(type, r);
            String what = type == MissionType.MISSION ? "upload" : type.label();
            progress(uploadError != null ? what + " verified by download (" + uploadError + ")"
                    : what + " verified" + (uploadNote.isEmpty() ? "" : " (" + uploadNote + ")"));
            nextList(lists, plan);
            return CompletionState.IN_PROGRESS;
        }
    }

    /** The id a transfer of the mission gave, if any: its upload's final ACK, or its verifying download's count. */
    private void noteMissionId(MissionType type, TransferResult r) {
        if (type == MissionType.MISSION && r.success() && r.planId() != 0) {
            feasibility.uploaded(r.planId());
        }
    }

    /** The list in transfer is done: the next one, or ARM after the mission. */
    private void nextList(Deque<Map.Entry<MissionType, List<MissionItem>>> lists, Plan plan) {
        lists.poll();
        enter(lists.isEmpty() ? new Arming(plan) : new Uploading(lists, plan));
    }

    /**
     * The first item current for a family armed in AUTO, its arming mode if it has one, then arm;
     * arming is retried until the deadline.
     */
    private final class Arming extends Stage {
        private final Plan plan;
        private final CommandSteps commands = commandSteps(what -> { });
        private final CommandSteps before = commandSteps(what -> { });
        private final long deadlineOfCheck;
        /** When the vehicle's MISSION_CURRENT first said it found the mission infeasible; -1 before. */
        private long infeasibleAt = -1;
        private boolean armModeSet;
        private CompletableFuture<CommandResult> pending;
        private long nextAttempt;

        Arming(Plan plan) {
            super(FlightState.ARM, config.arm());
            this.plan = plan;
            nextAttempt = clock().nanoTime();
            deadlineOfCheck = nextAttempt + MISSION_CHECK_WAIT.toNanos();
            if (armsInAuto()) {
                before.add(firstItemCurrent());
            }
        }

        @Override
        boolean triggersCamera() {
            return plan.triggersCamera();
        }

        @Override
        CompletionState step(long now) {
            if (!before.run(now)) {
                return before.failure() != null ? fail(before.failure()) : CompletionState.IN_PROGRESS;
            }
            if (rules.checksMissionAfterUpload()) {
                CompletionState checking = missionCheck(now);
                if (checking != null) {
                    return checking;
                }
            }
            var armMode = rules.armMode();
            if (armMode.isPresent() && !armModeSet) {
                String mode = armMode.get();
                if (pending == null) {
                    pending = watch(setMode(mode));
                }
                CommandResult r = answer();
                if (r == null) {
                    return CompletionState.IN_PROGRESS;
                }
                if (!commands.tookEffect(r, st -> st.inMode(mode))) {
                    return fail(commands.refusal(mode, r));
                }
                armModeSet = true;
            }
            if (pending == null) {
                if (now < nextAttempt) {
                    return CompletionState.IN_PROGRESS;
                }
                pending = watch(vehicle.command(MAV_CMD.MAV_CMD_COMPONENT_ARM_DISARM, 1));
            }
            CommandResult r = answer();
            if (r == null) {
                return CompletionState.IN_PROGRESS;
            }
            if (commands.tookEffect(r, VehicleState::armed)) {
                progress("armed");
                enter(new Starting(plan));
                return CompletionState.IN_PROGRESS;
            }
            if (now + config.retry().toNanos() > deadline) {
                return fail("vehicle " + vehicle.vehicleId() + " refused to arm for " + config.arm().toSeconds() + " s: "
                        + lastArmText(r));
            }
            nextAttempt = now + config.retry().toNanos();
            return CompletionState.IN_PROGRESS;
        }

        /**
         * Null once the vehicle found the mission feasible ({@link FeasibilityWatch}); else the stage's state while
         * it has not said, or its failure. The vehicle's reasons are what it said since the upload began, awaited
         * a little after its verdict. A vehicle that does not name its missions cannot tell its verdict on this one
         * from the earlier one's: a severe text is then taken as its refusal.
         */
        private CompletionState missionCheck(long now) {
            String refused = "vehicle " + vehicle.vehicleId() + " found the mission infeasible";
            switch (feasibility.verdict()) {
                case FEASIBLE -> {
                    return null;
                }
                case INFEASIBLE -> {
                    infeasibleAt = infeasibleAt < 0 ? now : infeasibleAt;
                    String said = words.quoteSince(missionUploadBegan, now);
                    if (!said.isEmpty()) {
                        return fail(refused + ": " + said);
                    }
                    if (!feasibility.unchanged() && now - infeasibleAt < VehicleWords.WAIT_NANOS) {
                        return CompletionState.IN_PROGRESS;
                    }
                    return fail(refused + (feasibility.unchanged()
                            ? " when it was given it before: it holds this same mission, and does not check it again"
                            : " (MISSION_CURRENT: no mission) and said nothing of why"));
                }
                default -> {
                    var severe = words.firstSevere(missionUploadBegan);
                    if (severe.isPresent() && !feasibility.namesMissions()) {
                        return fail(refused + ": '" + severe.get().text() + "'");
                    }
                    return now < deadlineOfCheck ? CompletionState.IN_PROGRESS : fail("vehicle " + vehicle.vehicleId()
                            + " did not find the mission feasible within " + MISSION_CHECK_WAIT.toSeconds() + " s: "
                            + missionCurrentSays(now));
                }
            }
        }

        /** What MISSION_CURRENT says when the vehicle's verdict did not come, and what the vehicle said since the upload. */
        private String missionCurrentSays(long now) {
            String said = words.quoteSince(missionUploadBegan, now);
            return missionCurrentSays() + (said.isEmpty() ? "" : "; the vehicle said " + said);
        }

        private String missionCurrentSays() {
            if (feasibility.lastTotal() != plan.items().size() - 1) {
                return "MISSION_CURRENT counts " + feasibility.lastTotal() + " items, not the mission's " + (plan.items().size() - 1);
            }
            int reported = feasibility.lastState();
            String state = reported == MISSION_STATE.MISSION_STATE_NO_MISSION ? "no mission"
                    : EnumNames.name(MISSION_STATE.class, "MISSION_STATE_", reported);
            return feasibility.unchecked()
                    ? "MISSION_CURRENT still names no current item and says " + state + ": the vehicle has not shown its check"
                    : "MISSION_CURRENT still says " + state;
        }

        private CommandResult answer() {
            if (pending == null || !pending.isDone()) {
                return null;
            }
            CommandResult r = pending.join();
            pending = null;
            return r;
        }

        private String lastArmText(CommandResult r) {
            List<String> texts = vehicle.state().statusTexts();
            for (int i = texts.size() - 1; i >= 0; i--) {
                if (texts.get(i).contains("Arm")) {
                    return texts.get(i);
                }
            }
            return r.resultName();
        }
    }

    /**
     * The fence on if the script says so, the first item current, AUTO, and MISSION_START where the
     * family needs it. From the first item whatever the vehicle ran before: ArduPilot keeps its
     * mission's current item across an upload, and a copter on the ground refuses AUTO unless that
     * item leads to a take-off.
     */
    private final class Starting extends Stage {
        private final Plan plan;
        private final CommandSteps steps = commandSteps(what -> { });
        /** The vehicle's reboots before the flight, and when AUTO was first asked: from then on its words count. */
        private final int rebootsBefore = vehicle.state().reboots();
        private long autoAsked = -1;

        Starting(Plan plan) {
            super(FlightState.START, config.start());
            this.plan = plan;
            if (mission.fenceEnabled() && rules.fenceSwitch()) {
                steps.add(new CommandSteps.Step("MAV_CMD_DO_FENCE_ENABLE 1", () -> vehicle.command(
                        MAV_CMD.MAV_CMD_DO_FENCE_ENABLE, 1, 0), st -> false));
            }
            rules.afterArming().forEach(c -> steps.add(familyStep(c)));
            if (!armsInAuto() && !rules.missionStartFromFirstItem()) {
                steps.add(firstItemCurrent());
            }
            String auto = rules.missionMode();
            steps.add(new CommandSteps.Step(auto, () -> {
                refusals.begin();
                if (autoAsked < 0) {
                    autoAsked = clock().nanoTime();
                }
                return setMode(auto);
            }, st -> st.inMode(auto), rules.autoWaitsAfterArming()));
            if (rules.needsMissionStart()) {
                steps.add(new CommandSteps.Step("MAV_CMD_MISSION_START", () -> vehicle.command(MAV_CMD.MAV_CMD_MISSION_START, 0, 0),
                        st -> st.missionState() == MISSION_STATE.MISSION_STATE_ACTIVE));
            }
        }

        @Override
        boolean triggersCamera() {
            return plan.triggersCamera();
        }

        @Override
        CompletionState step(long now) {
            if (steps.run(now)) {
                progress("started");
                enter(new Following(plan, autoAsked, rebootsBefore));
            }
            return steps.failure() != null ? fail(steps.failure()) : CompletionState.IN_PROGRESS;
        }
    }

    /**
     * Follows the flight: items reached, ground-side commands and jumps at their items, the end
     * (MissionEnd), someone else's hand (Takeovers), faults (FlightAlarms) and stalls (StallWatch).
     */
    private final class Following extends Stage {
        private final Plan plan;
        private final Takeovers takeovers;
        private final FlightAlarms alarms;
        private final StallWatch stalls;
        private final Map<JumpToItem, Integer> jumpsLeft = new HashMap<>();
        /** Whether the vehicle has shown the mission active (MISSION_CURRENT), so its current item counts as progress. */
        private boolean active;
        private int sentUpTo;
        private int reported;
        private long resendJump;

        Following(Plan plan, long since, int rebootsBefore) {
            super(FlightState.RUNNING, Duration.ZERO);
            this.plan = plan;
            ItemNames names = new ItemNames(plan.items());
            String id = vehicle.vehicleId();
            takeovers = new Takeovers(rules, names, id, words, MissionEnd.lastNavigation(plan.items()), config.modeGrace(),
                    config.takeoverTimeout());
            alarms = new FlightAlarms(rules, names, id, words, since, rebootsBefore);
            stalls = new StallWatch(rules, names, id, config.stallWarning(), config.stallLimit());
            plan.keyed().values().forEach(cmds -> cmds.stream().filter(c -> c instanceof JumpToItem)
                    .forEach(c -> jumpsLeft.put((JumpToItem) c, ((JumpToItem) c).repetitions())));
        }

        @Override
        boolean triggersCamera() {
            return plan.triggersCamera();
        }

        @Override
        CompletionState step(long now) {
            VehicleState s = vehicle.state();
            if (s.missionState() == MISSION_STATE.MISSION_STATE_ACTIVE) {
                active = true;
            }
            int last = plan.items().size() - 1;
            if (!jumpSeen(s, now)) {
                return CompletionState.IN_PROGRESS;
            }
            int r = reached.get();
            if (active && s.missionState() == MISSION_STATE.MISSION_STATE_ACTIVE) {
                r = Math.max(r, s.missionSeq() - 1);
            }
            if (r > reported) {
                reported = r;
                progress("item " + Math.min(r, last) + " of " + last + " reached");
            }
            if (sendKeyedCommands(r, now)) {
                // The flight goes back: what the vehicle said before the jump no longer tells its end.
                return CompletionState.IN_PROGRESS;
            }
            boolean auto = s.inMode(rules.missionMode());
            MissionEnd.Verdict verdict = plan.end().judge(s, r, auto, now);
            var refused = refusals.refusal();
            if (verdict.error() == null && refused.isPresent()) {
                return fail(refused.get());
            }
            if (verdict.done()) {
                MissionExecutor.this.state = FlightState.DONE;
                for (FlightRules.FamilyCommand c : rules.afterLanding()) {
                    vehicle.command(c.command(), c.params());
                    progress(c.what());
                }
                progress("done");
                return CompletionState.DONE;
            }
            if (verdict.error() != null) {
                return fail(verdict.error());
            }
            return watch(s, plan.end().current(s, r), auto, now);
        }

        /** Someone else's hand, the faults, and a stall: an error, or a line for a takeover, a hand-back or a stall's warning. */
        private CompletionState watch(VehicleState s, int current, boolean auto, long now) {
            Takeovers.Look look = takeovers.look(s, auto, current, now);
            var alarm = alarms.judge(s, current, takeovers.paused() || plan.end().landing(), now);
            if (alarm.isPresent()) {
                return fail(alarm.get());
            }
            switch (look.hand()) {
                case FAILED -> {
                    return fail(look.text());
                }
                case TAKEN_OVER -> report(EventKind.TAKEN_OVER, look.text() + ", mission " + mission.getId() + " paused until " + rules.missionMode()
                        + " is back, for " + config.takeoverTimeout().toSeconds() + " s at most");
                case HANDED_BACK -> report(EventKind.HANDED_BACK, look.text() + ", mission " + mission.getId() + " goes on");
                default -> { }
            }
            StallWatch.Notice stall = stalls.look(s, current, auto && !takeovers.paused(), now);
            if (stall.error() != null) {
                return fail(stall.error());
            }
            if (stall.warning() != null) {
                report(EventKind.STALLING, stall.warning());
            }
            return CompletionState.IN_PROGRESS;
        }

        /**
         * After a jump, MISSION_CURRENT and MISSION_ITEM_REACHED from before it (items past the jump's key)
         * still arrive: they are ignored until MISSION_CURRENT is back at or before the jump's item. The jump's
         * MISSION_SET_CURRENT is sent again each second until then, in case it was lost.
         */
        private boolean jumpSeen(VehicleState s, long now) {
            JumpToItem jumping = reached.jumpPending(s);
            if (jumping == null) {
                return true;
            }
            if (now >= resendJump) {
                send(jumping);
                resendJump = now + JUMP_RESEND.toNanos();
            }
            return false;
        }

        /**
         * Sends the non-mission commands keyed by the items reached; a jump goes back and runs them again.
         * True when a jump was sent.
         */
        private boolean sendKeyedCommands(int r, long now) {
            if (r <= sentUpTo) {
                return false;
            }
            for (Map.Entry<Integer, List<DroneCommand>> e : plan.keyed().subMap(sentUpTo, false, r, true).entrySet()) {
                for (DroneCommand c : e.getValue()) {
                    if (c instanceof JumpToItem jump) {
                        int left = jumpsLeft.getOrDefault(jump, 0);
                        if (left > 0) {
                            jumpsLeft.put(jump, left - 1);
                            refusals.jumped(jump.item());
                            send(jump);
                            progress("jump to item " + jump.item());
                            reached.jumped(jump);
                            resendJump = now + JUMP_RESEND.toNanos();
                            sentUpTo = jump.item() - 1;
                            reported = sentUpTo;
                            return true;
                        }
                    } else {
                        send(c);
                    }
                }
                sentUpTo = e.getKey();
            }
            return false;
        }
    }

    /**
     * The items the vehicle reported reached (MISSION_ITEM_REACHED, on the communications thread) and the
     * ground-side jump not yet seen on the vehicle (script thread): until the vehicle shows the jump, a
     * MISSION_ITEM_REACHED may be from before it.
     */
    private static final class ItemsReached {
        private int reached;
        private JumpToItem jumping;

        synchronized void reached(int seq) {
            if (jumping == null) {
                reached = Math.max(reached, seq);
            }
        }

        synchronized int get() {
            return reached;
        }

        synchronized void jumped(JumpToItem jump) {
            reached = jump.item() - 1;
            jumping = jump;
        }

        /** The jump still not seen on the vehicle (MISSION_CURRENT not yet back at or before its item), or null. */
        synchronized JumpToItem jumpPending(VehicleState s) {
            if (jumping != null && s.missionState() == MISSION_STATE.MISSION_STATE_ACTIVE && s.missionSeq() >= 0
                    && s.missionSeq() <= jumping.item()) {
                jumping = null;
            }
            return jumping;
        }
    }

    /** Armed in AUTO, a vehicle starts at once from its current item, which may be a previous flight's: item 1 is made current first. */
    private boolean armsInAuto() {
        return rules.armMode().filter(rules.missionMode()::equals).isPresent();
    }

    private CommandSteps.Step firstItemCurrent() {
        return new CommandSteps.Step("MAV_CMD_DO_SET_MISSION_CURRENT 1", () -> vehicle.command(
                MAV_CMD.MAV_CMD_DO_SET_MISSION_CURRENT, autopilot().vehicleSeq(1), 1), st -> st.missionSeq() == 1);
    }

    /** A family's command, done once accepted: what it changes is not in the vehicle's telemetry. */
    private CommandSteps.Step familyStep(FlightRules.FamilyCommand c) {
        return new CommandSteps.Step(c.what(), () -> vehicle.command(c.command(), c.params()), st -> false);
    }

    private CommandSteps commandSteps(java.util.function.Consumer<String> waiting) {
        return new CommandSteps(vehicle.vehicleId(), vehicle::state, config.retry(), waiting, this::watch);
    }

    /** A ground-side command; a jump names its item the way the vehicle numbers them. */
    private void send(DroneCommand command) {
        DroneCommand sent = command instanceof JumpToItem jump ? jump.numbered(autopilot().vehicleSeq(jump.item())) : command;
        sent.messages(vehicle.system(), vehicle.component()).forEach(vehicle::send);
    }

    private Autopilot autopilot() {
        return vehicle.state().autopilot();
    }

    private CompletableFuture<CommandResult> setMode(String name) {
        VehicleState s = vehicle.state();
        OptionalLong mode = s.modes().number(name);
        if (mode.isEmpty()) {
            return CompletableFuture.completedFuture(new CommandResult(MAV_CMD.MAV_CMD_DO_SET_MODE, MAV_RESULT.MAV_RESULT_UNSUPPORTED, 0));
        }
        return vehicle.command(MAV_CMD.MAV_CMD_DO_SET_MODE, s.autopilot().setModeParams(mode.getAsLong()));
    }

    /** Steps the task tree as soon as the operation completes, not at the next tick. */
    private <T> CompletableFuture<T> watch(CompletableFuture<T> operation) {
        operation.whenComplete((r, e) -> vehicle.wake());
        return operation;
    }

    private CompletionState fail(String why) {
        failure = why;
        state = FlightState.ERROR;
        return CompletionState.error("mission " + mission.getId() + (vehicle != null ? " on vehicle " + vehicle.vehicleId() : "") + ": " + why);
    }

    /** Something a person watching the fleet should hear of at once: a vehicle event, and the mission's line. */
    private void report(EventKind kind, String what) {
        vehicle.event(kind, what);
        progress(what);
    }

    private void progress(String what) {
        context().listener().message("mission " + mission.getId() + " on vehicle " + vehicle.vehicleId() + ": " + what);
    }
}
