package dolphin.sim;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;

/**
 * A vehicle's injected faults: each waits until its time after the vehicle's first arming, then runs
 * until it is over. Several may run at once; while any of them holds the vehicle's flight, its
 * mission, RTL and LAND do not move it.
 */
final class FaultSchedule {

    private record Waiting(long afterArmingNanos, Fault fault) {
    }

    private final List<Waiting> waiting = new ArrayList<>();
    private final List<Fault> running = new ArrayList<>();

    /** The faults of {@code faults} that happen to vehicle {@code sysid}, a vehicle of kind {@code kind} running {@code firmware}. */
    FaultSchedule(List<SimFault> faults, int sysid, VehicleKind kind, Firmware firmware) {
        for (SimFault f : faults) {
            if (f.appliesTo(sysid)) {
                waiting.add(new Waiting((long) (f.afterArmingSeconds() * 1e9), f.start(kind, firmware)));
            }
        }
    }

    /**
     * Steps the running faults by {@code dt} seconds, then begins those whose time has come at clock
     * time {@code now}, given when the vehicle first armed ({@code armedAt}; negative: not yet).
     */
    void tick(long now, long armedAt, double dt, FaultHost vehicle) {
        running.removeIf(f -> !f.step(vehicle, dt));
        if (armedAt < 0) {
            return;
        }
        for (Iterator<Waiting> it = waiting.iterator(); it.hasNext(); ) {
            Waiting w = it.next();
            if (now - armedAt >= w.afterArmingNanos()) {
                it.remove();
                w.fault().begin(vehicle);
                running.add(w.fault());
            }
        }
    }

    boolean holdsFlight(FaultHost vehicle) {
        return running.stream().anyMatch(f -> f.holdsFlight(vehicle));
    }
}
