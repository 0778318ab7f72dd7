package dolphin.sim;

import dolphin.mavlink.Autopilot;
import java.util.ArrayList;
import java.util.List;

/**
 * Behaviour knobs of simulated vehicles.
 *
 * @param warmupSeconds the vehicle has no position estimate, so refuses a home and arming ("PreArm: ..."), until
 *        this long after boot (ArduCopter SITL: 41 s, when its EKF starts to use GPS; docs/mavlink.md)
 * @param drainPercentPerMinute battery use while armed (ArduCopter SITL: about 14 %/min)
 * @param messageIntervalSupported false makes MAV_CMD_SET_MESSAGE_INTERVAL UNSUPPORTED (older firmware)
 * @param refuseModeChanges true makes every mode change fail
 * @param missionCapacity the most mission items (home included) the vehicle stores; a larger
 *        MISSION_COUNT is refused with NO_SPACE (ArduPilot's limit depends on its storage; 700 here)
 * @param diveSilenceMetres deeper than this below the surface a sub sends and hears nothing, as its radio
 *        under water; infinite (the default): always heard
 * @param ftp true (the default): the vehicle serves MAVLink FTP (its @MISSION files) and says so in
 *        AUTOPILOT_VERSION; false: FILE_TRANSFER_PROTOCOL gets no answer and the capability bit is clear,
 *        as firmware built without FTP
 * @param faults the faults injected into the vehicles, each at its time after a vehicle's first arming
 *        (docs/mavlink.md, "Faults")
 * @param autopilot the autopilot the vehicles run: ArduPilot (the default) or PX4
 */
public record SimOptions(double warmupSeconds, double drainPercentPerMinute, boolean messageIntervalSupported,
                         boolean refuseModeChanges, int missionCapacity, double diveSilenceMetres, boolean ftp,
                         List<SimFault> faults, Autopilot autopilot) {

    public static final int DEFAULT_MISSION_CAPACITY = 700;
    public static final SimOptions DEFAULT = new SimOptions(0, 14, true, false, DEFAULT_MISSION_CAPACITY,
            Double.POSITIVE_INFINITY, true, List.of(), Autopilot.ARDUPILOT);

    public SimOptions(double warmupSeconds, double drainPercentPerMinute, boolean messageIntervalSupported,
                      boolean refuseModeChanges) {
        this(warmupSeconds, drainPercentPerMinute, messageIntervalSupported, refuseModeChanges, DEFAULT_MISSION_CAPACITY,
                Double.POSITIVE_INFINITY, true, List.of(), Autopilot.ARDUPILOT);
    }

    public SimOptions {
        faults = List.copyOf(faults);
        SimAutopilot.of(autopilot); // the fleet simulates ArduPilot and PX4 only: any other is refused here
        if (missionCapacity < 1) {
            throw new IllegalArgumentException("the mission capacity must hold at least home, got " + missionCapacity);
        }
        if (!(diveSilenceMetres >= 0)) {
            throw new IllegalArgumentException("the dive silence must be a depth in metres, 0 or more, got " + diveSilenceMetres);
        }
    }

    public SimOptions withWarmup(double seconds) {
        return new SimOptions(seconds, drainPercentPerMinute, messageIntervalSupported, refuseModeChanges, missionCapacity,
                diveSilenceMetres, ftp, faults, autopilot);
    }

    public SimOptions withDrain(double percentPerMinute) {
        return new SimOptions(warmupSeconds, percentPerMinute, messageIntervalSupported, refuseModeChanges, missionCapacity,
                diveSilenceMetres, ftp, faults, autopilot);
    }

    public SimOptions withoutMessageInterval() {
        return new SimOptions(warmupSeconds, drainPercentPerMinute, false, refuseModeChanges, missionCapacity, diveSilenceMetres,
                ftp, faults, autopilot);
    }

    public SimOptions withMissionCapacity(int items) {
        return new SimOptions(warmupSeconds, drainPercentPerMinute, messageIntervalSupported, refuseModeChanges, items,
                diveSilenceMetres, ftp, faults, autopilot);
    }

    /** Subs deeper than {@code metres} below the surface are cut off. */
    public SimOptions withDiveSilence(double metres) {
        return new SimOptions(warmupSeconds, drainPercentPerMinute, messageIntervalSupported, refuseModeChanges, missionCapacity,
                metres, ftp, faults, autopilot);
    }

    /** Vehicles without MAVLink FTP: FILE_TRANSFER_PROTOCOL unanswered, no FTP bit in AUTOPILOT_VERSION. */
    public SimOptions withoutFtp() {
        return new SimOptions(warmupSeconds, drainPercentPerMinute, messageIntervalSupported, refuseModeChanges, missionCapacity,
                diveSilenceMetres, false, faults, autopilot);
    }

    /** Vehicles that run {@code a} (ArduPilot or PX4). */
    public SimOptions withAutopilot(Autopilot a) {
        return new SimOptions(warmupSeconds, drainPercentPerMinute, messageIntervalSupported, refuseModeChanges, missionCapacity,
                diveSilenceMetres, ftp, faults, a);
    }

    /** With {@code fault} injected too. */
    public SimOptions withFault(SimFault fault) {
        List<SimFault> more = new ArrayList<>(faults);
        more.add(fault);
        return new SimOptions(warmupSeconds, drainPercentPerMinute, messageIntervalSupported, refuseModeChanges, missionCapacity,
                diveSilenceMetres, ftp, more, autopilot);
    }
}
