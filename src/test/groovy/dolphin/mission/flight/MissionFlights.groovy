package dolphin.mission.flight

import dolphin.core.Allocation
import dolphin.core.CompletionState
import dolphin.core.Environment
import dolphin.core.ManualClock
import dolphin.core.Node
import dolphin.core.Position
import dolphin.core.RuntimeListener
import dolphin.core.TaskContext
import dolphin.mission.dsl.MissionDsl
import dolphin.mission.flight.MissionExecutor.FlightState
import spock.lang.Specification

/**
 * What the executor specs share: a ManualClock, the script's messages, a fleet of FakeFlightVehicles,
 * and the script thread's part, stepping executors at once (as a completed command or transfer wakes
 * the script) or at each 100 ms tick. No socket, no thread, no sleep.
 */
abstract class MissionFlights extends Specification {

    ManualClock clock = new ManualClock()
    List<String> messages = []
    RuntimeListener listener = new RuntimeListener() {
        @Override
        void message(String text) { messages << text }
    }
    FakeFlightVehicle vehicle = new FakeFlightVehicle(clock)
    Map<String, FakeFlightVehicle> fleet = ['1': vehicle]
    MissionExecutor executor

    /** Take-off at 20 m, a waypoint 40 m north, a landing there: 4 items with home. */
    static MissionTask hop() {
        MissionDsl.mission {
            name 'hop'
            takeOff Position.fromDegrees(40.444233, -7.375234, 840)
            goPos 40.4446, -7.375234, 840
            landingPoint 40.4446, -7.375234, 820
        }
    }

    /** The flight's messages as the script shows them. */
    static List<String> said(String mission = 'hop', String id = '1', List<String> what) {
        what.collect { "mission ${mission} on vehicle ${id}: ${it}".toString() }
    }

    MissionExecutor launch(MissionTask task, FakeFlightVehicle v = vehicle) {
        fleet[v.id] = v
        def e = new MissionExecutor(task, { Node n -> fleet[n.id] })
        def allocation = new Allocation()
        allocation.assign([v.node])
        e.initialize(new TaskContext(clock, listener), allocation)
        e.start()
        executor = executor ?: e
        e
    }

    CompletionState step(MissionExecutor e = executor) {
        e.step()
    }

    /** Steps at each 100 ms tick after now, up to {@code seconds} after the start, until the executor completes. */
    CompletionState runTo(double seconds, MissionExecutor e = executor) {
        long end = Math.round(seconds * 1e9)
        while (clock.nanoTime() < end && !e.completed) {
            clock.advance(Environment.TICK)
            e.step()
        }
        e.completionState
    }

    /** Steps at once until the executor reaches {@code state} (a willing vehicle gets there without time passing). */
    void stepUntil(FlightState state, MissionExecutor e = executor) {
        for (int i = 0; i < 20 && e.state() != state; i++) {
            assert !e.completed: "${e.mission().id} ended before ${state}: ${e.completionState}; messages ${messages}"
            e.step()
        }
        assert e.state() == state: "${e.mission().id} stuck in ${e.state()}; messages ${messages}"
    }

    /** As a willing vehicle: ends the transfer or accepts the command the executor waits for, then steps; until it is in {@code state}. */
    void driveTo(FlightState state, MissionExecutor e = executor, FakeFlightVehicle v = vehicle) {
        for (int i = 0; i < 30 && e.state() != state; i++) {
            def t = v.transfers.find { !it.result.done }
            def c = v.commands.find { !it.answer.done }
            if (t != null) {
                t.upload ? v.completeUpload(t) : v.completeDownload(t)
            } else if (c != null) {
                v.accept(c)
            }
            e.step()
        }
        assert e.state() == state: "${e.mission().id} stuck in ${e.state()}; messages ${messages}"
    }

    double now() { clock.seconds() }
}
