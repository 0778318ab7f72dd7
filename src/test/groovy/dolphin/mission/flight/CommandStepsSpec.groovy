package dolphin.mission.flight

import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_RESULT
import dolphin.core.Position
import dolphin.mavlink.CommandResult
import dolphin.mavlink.VehicleState
import java.time.Duration
import java.util.concurrent.CompletableFuture
import spock.lang.Specification

/**
 * PREPARE's and START's commands on a fake sender (each command a future the test completes, as
 * the vehicle's COMMAND_ACK would) and a fake clock (the nanoseconds given to run): no sockets, no
 * sleeps. The readiness they follow is ReadinessSpec's.
 */
class CommandStepsSpec extends Specification {

    static final long SECOND = 1_000_000_000L
    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)

    VehicleState vehicle = ReadinessSpec.vehicle(prearm: false, texts: ['PreArm: Need Position Estimate'])
    List<String> waited = []
    /** What was sent, in order, and the futures the vehicle answers. */
    List<String> sent = []
    List<CompletableFuture<CommandResult>> answers = []
    int watched
    CommandSteps steps = new CommandSteps('1', { vehicle }, Duration.ofSeconds(2), { waited << it },
            { f -> watched++; f })

    CommandSteps.Step step(String what, boolean waitable = false, Closure<Boolean> effect = { false }) {
        new CommandSteps.Step(what, {
            sent << what
            def f = new CompletableFuture<CommandResult>()
            answers << f
            f
        }, { s -> effect(s) }, waitable)
    }

    static CommandResult ack(int command, int result, int attempts = 1) {
        new CommandResult(command, result, attempts)
    }

    def "DO_SET_HOME refused for now is sent again after the retry pause, saying what it waits for, until it is accepted"() {
        given:
        steps.add(step('DO_SET_HOME', true))
        steps.add(step('AUTO'))

        expect: 'sent at once, and waited for'
        !steps.run(0)
        sent == ['DO_SET_HOME']
        watched == 1

        when: 'FAILED: no position estimate yet'
        answers[0].complete(ack(MAV_CMD.MAV_CMD_DO_SET_HOME, MAV_RESULT.MAV_RESULT_FAILED))

        then: 'it says why, in the vehicle\'s words, and does not send again before 2 s'
        !steps.run(SECOND)
        waited == ['DO_SET_HOME FAILED (PreArm: Need Position Estimate)']
        !steps.run(2 * SECOND)
        sent == ['DO_SET_HOME']

        when: 'the pause is over: sent again, TEMPORARILY_REJECTED, then again, ACCEPTED'
        steps.run(3 * SECOND)
        answers[1].complete(ack(MAV_CMD.MAV_CMD_DO_SET_HOME, MAV_RESULT.MAV_RESULT_TEMPORARILY_REJECTED))
        steps.run(3 * SECOND)
        steps.run(5 * SECOND)
        answers[2].complete(ack(MAV_CMD.MAV_CMD_DO_SET_HOME, MAV_RESULT.MAV_RESULT_ACCEPTED))
        boolean done = steps.run(5 * SECOND)

        then: 'the next step is sent in the same step of the clock'
        !done
        sent == ['DO_SET_HOME', 'DO_SET_HOME', 'DO_SET_HOME', 'AUTO']
        waited == ['DO_SET_HOME FAILED (PreArm: Need Position Estimate)', 'DO_SET_HOME TEMPORARILY_REJECTED (PreArm: Need Position Estimate)']

        when:
        answers[3].complete(ack(MAV_CMD.MAV_CMD_DO_SET_MODE, MAV_RESULT.MAV_RESULT_ACCEPTED))

        then:
        steps.run(5 * SECOND)
        steps.failure() == null
    }

    def "#what fails the steps with a message naming the vehicle and the command"() {
        given:
        steps.add(step('AUTO', waitable))
        steps.add(step('MAV_CMD_MISSION_START'))

        when:
        steps.run(0)
        answers[0].complete(ack(MAV_CMD.MAV_CMD_DO_SET_MODE, result, 5))

        then:
        !steps.run(0)
        steps.failure() == failure
        sent == ['AUTO']
        !steps.run(10 * SECOND)
        sent == ['AUTO']

        where:
        what                                 | waitable | result                                  || failure
        'a refusal'                          | false    | MAV_RESULT.MAV_RESULT_DENIED            || 'vehicle 1 refused AUTO: DENIED'
        'FAILED, for a step that cannot wait' | false   | MAV_RESULT.MAV_RESULT_FAILED            || 'vehicle 1 refused AUTO: FAILED'
        'UNSUPPORTED, even for one that can' | true     | MAV_RESULT.MAV_RESULT_UNSUPPORTED       || 'vehicle 1 refused AUTO: UNSUPPORTED'
        'silence'                            | false    | CommandResult.NO_ACK                    || 'vehicle 1 did not answer AUTO: no COMMAND_ACK after 5 attempt(s)'
    }

    def "a command never acknowledged counts as done when the vehicle's state shows it took effect (every ACK lost)"() {
        given:
        steps.add(step('DO_SET_HOME', true) { VehicleState s -> s.home() != null })

        when:
        steps.run(0)
        vehicle = vehicle.withHome(HOME)
        answers[0].complete(ack(MAV_CMD.MAV_CMD_DO_SET_HOME, CommandResult.NO_ACK, 5))

        then:
        steps.run(0)
        steps.failure() == null
        waited.empty
    }
}
