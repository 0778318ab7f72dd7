package dolphin.mission.flight

import com.MAVLink.enums.MAV_LANDED_STATE
import com.MAVLink.enums.MAV_RESULT
import com.MAVLink.enums.MAV_SEVERITY
import com.MAVLink.enums.MISSION_STATE
import dolphin.core.Allocation
import dolphin.core.CompletionState
import dolphin.core.Position
import dolphin.core.TaskContext
import dolphin.mavlink.CommandResult
import dolphin.mavlink.VehicleFamily
import dolphin.mission.dsl.MissionDsl
import dolphin.mission.flight.MissionExecutor.FlightState
import dolphin.mission.model.MissionItem
import dolphin.mission.model.MissionType
import java.time.Duration
import spock.lang.Unroll

import static dolphin.mission.flight.FakeFlightVehicle.HOME

/**
 * The MissionExecutor under faults, on a FakeFlightVehicle and a ManualClock (no socket, no thread,
 * no sleep): a vehicle that is not ready or never becomes ready, commands refused or unanswered
 * (every COMMAND_ACK lost on a bad link: the vehicle's state decides), transfers that fail or never
 * end, a mission the vehicle holds differently, and someone else's hand during the flight. Each
 * deadline is met to the 100 ms tick. Link faults within a transfer are MissionTransferSpec's.
 */
class MissionExecutorFaultsSpec extends MissionFlights {

    static final int NO_ACK = CommandResult.NO_ACK
    static final int DONE = FakeFlightVehicle.DONE_WITHOUT_ACK

    /** Take-off, two waypoints, a landing: 5 items with home. */
    static MissionTask hop5() {
        MissionDsl.mission {
            name 'hop'
            takeOff Position.fromDegrees(40.444233, -7.375234, 840)
            goPos 40.4444, -7.375234, 840
            goPos 40.4446, -7.375234, 840
            landingPoint 40.4446, -7.375234, 820
        }
    }

    /** The executor's error as the script sees it. */
    String failure(MissionExecutor e = executor) {
        assert e.completionState.error: "${e.mission().id} did not fail: ${e.completionState}; messages ${messages}"
        e.completionState.message
    }

    // ---- PREPARE

    def "a vehicle that never becomes ready: it says once per change what it waits for, uploads nothing, and fails just after the prepare deadline in the vehicle's words"() {
        given: 'a vehicle without a position estimate; 15 s after boot it says why; a 40 s readiness deadline'
        vehicle.executorConfig = MissionExecutorConfig.DEFAULT.withPrepare(Duration.ofSeconds(40))
        vehicle.prearm(false)
        clock.schedule(Duration.ofSeconds(15)) { vehicle.text('PreArm: Need Position Estimate') }

        when:
        launch(hop())
        step()
        def at40 = runTo(40)

        then:
        at40 == CompletionState.IN_PROGRESS
        executor.state() == FlightState.PREPARE
        messages == ['waiting for vehicle 1: no position estimate yet', 'waiting for vehicle 1: PreArm: Need Position Estimate']

        when:
        def after = runTo(41)

        then:
        after.error
        now() == 40.1d
        failure() == 'mission hop on vehicle 1: vehicle 1 was not ready within 40 s: PreArm: Need Position Estimate'
        executor.state() == FlightState.ERROR
        vehicle.log.empty
        vehicle.executors == ['flying hop', 'landed hop']
    }

    def "a vehicle booting: each wait said once, in order, until it is ready; then how long it waited, and the upload"() {
        given:
        vehicle.prearm(false)
        def at = { double s, Closure change -> clock.schedule(Duration.ofMillis(Math.round(s * 1000))) { change() } }
        at(5) { vehicle.at(0, 0); vehicle.state = vehicle.state.withEkfFlags(167) }
        at(10) { vehicle.state = vehicle.state.withEkfFlags(831) }
        at(15) { vehicle.state = vehicle.state.withHome(HOME); vehicle.text('PreArm: Gyros inconsistent') }
        at(30) { vehicle.prearm(true) }

        when:
        launch(hop())
        step()
        runTo(29.9)

        then:
        messages == ['waiting for vehicle 1: no position estimate yet',
                     'waiting for vehicle 1: no position estimate yet (EKF: no absolute horizontal position)',
                     'waiting for vehicle 1: no home position yet',
                     'waiting for vehicle 1: PreArm: Gyros inconsistent']
        vehicle.log.empty

        when:
        runTo(30)

        then:
        messages.drop(4) == said(['vehicle ready after 30 s', 'uploading 4 items'])
        vehicle.log == ['30.0 upload mission: 4 items']
    }

    @Unroll
    def "a vehicle not ready within the deadline, #why: '#what'"() {
        given:
        vehicle.executorConfig = MissionExecutorConfig.DEFAULT.withPrepare(Duration.ofSeconds(10))
        vehicle.ready()
        vehicle.state = vehicle.state.withHome(null)
        vehicle.answers['DO_SET_HOME 40.444233 -7.375234 820.0'] = MAV_RESULT.MAV_RESULT_FAILED
        def task = withHome ? MissionDsl.mission {
            name 'hop'
            home Position.fromDegrees(40.444233, -7.375234, 820)
            takeOff Position.fromDegrees(40.444233, -7.375234, 840)
        } : hop()

        when:
        launch(task)
        step()
        runTo(11)

        then:
        now() == 10.1d
        failure() == "mission hop on vehicle 1: vehicle 1 was not ready within 10 s: ${what}".toString()
        vehicle.commands*.time == (withHome ? [0.0d, 2.0d, 4.0d, 6.0d, 8.0d, 10.0d] : [])

        where:
        why                                                 | withHome || what
        'no home and no text'                               | false    || 'no home position yet'
        'DO_SET_HOME FAILED throughout, the vehicle silent' | true     || 'DO_SET_HOME FAILED'
    }

    def "a vehicle that is not a MAVLink vehicle fails at once"() {
        given:
        def e = new MissionExecutor(hop(), { null })
        def allocation = new Allocation()
        allocation.assign([vehicle.node])
        e.initialize(new TaskContext(clock, listener), allocation)
        e.start()

        expect:
        e.step().message == 'mission hop: vehicle 1 is not a MAVLink vehicle'
        e.state() == FlightState.ERROR
        vehicle.executors.empty
    }

    @Unroll
    def "PREPARE's #command answered #answer: #outcome"() {
        given: 'a copter flying another mission in AUTO, and a mission naming its home'
        vehicle.ready()
        vehicle.heartbeat(true, 'AUTO')
        vehicle.missionCurrent(3)
        vehicle.state = vehicle.state.withHome(HOME.displace(100, 0, 0))
        vehicle.autopilot = true
        vehicle.answers[command] = result
        def task = MissionDsl.mission {
            name 'hop'
            home Position.fromDegrees(40.444233, -7.375234, 820)
            takeOff Position.fromDegrees(40.444233, -7.375234, 840)
        }

        when:
        launch(task)
        step()

        then:
        vehicle.commands*.text == sent
        (error == null) ? executor.state() == FlightState.UPLOAD : failure() == "mission hop on vehicle 1: ${error}".toString()

        where:
        command                                 | answer                     | result                       || sent                                                            | error
        'DO_SET_MODE LOITER'                    | 'DENIED'                   | MAV_RESULT.MAV_RESULT_DENIED || ['DO_SET_MODE LOITER']                                          | 'vehicle 1 refused leaving AUTO for LOITER before the new mission: DENIED'
        'DO_SET_MODE LOITER'                    | 'nothing (mode unchanged)' | NO_ACK                       || ['DO_SET_MODE LOITER']                                          | 'vehicle 1 did not answer leaving AUTO for LOITER before the new mission: no COMMAND_ACK after 5 attempt(s)'
        'DO_SET_MODE LOITER'                    | 'nothing (mode changed)'   | DONE                         || ['DO_SET_MODE LOITER', 'DO_SET_HOME 40.444233 -7.375234 820.0'] | null
        'DO_SET_HOME 40.444233 -7.375234 820.0' | 'DENIED'                   | MAV_RESULT.MAV_RESULT_DENIED || ['DO_SET_MODE LOITER', 'DO_SET_HOME 40.444233 -7.375234 820.0'] | 'vehicle 1 refused DO_SET_HOME: DENIED'
        'DO_SET_HOME 40.444233 -7.375234 820.0' | 'nothing (home not moved)' | NO_ACK                       || ['DO_SET_MODE LOITER', 'DO_SET_HOME 40.444233 -7.375234 820.0'] | 'vehicle 1 did not answer DO_SET_HOME: no COMMAND_ACK after 5 attempt(s)'
        'DO_SET_HOME 40.444233 -7.375234 820.0' | 'nothing (home moved)'     | DONE                         || ['DO_SET_MODE LOITER', 'DO_SET_HOME 40.444233 -7.375234 820.0'] | null
        outcome = error ?: 'the upload starts'
    }

    def "an item lower than the vehicle's home plus 2 m fails the mission before the upload, naming it; allowBelowHome lets it fly"() {
        given:
        vehicle.ready()
        Closure low = { boolean allowed ->
            MissionDsl.mission {
                name 'hop'
                allowBelowHome allowed
                takeOff Position.fromDegrees(40.444233, -7.375234, 840)
                goPos 40.4446, -7.375234, 821
                landingPoint 40.4446, -7.375234, 820
            }
        }

        when:
        launch(low(false))
        step()

        then:
        failure() == "mission hop on vehicle 1: mission hop: item 2 (goPos, NAV_WAYPOINT) is 1.0 m above home (home at 820.0 m): lower" +
                " than the 2 m clearance, into the ground or nearly; only landings go lower. Raise it, or write 'allowBelowHome true'" +
                " in the mission if this is intended"
        vehicle.log.empty

        when:
        def allowed = launch(low(true))
        step(allowed)

        then:
        allowed.state() == FlightState.UPLOAD
    }

    // ---- UPLOAD and VERIFY

    @Unroll
    def "#what: #outcome"() {
        given: 'a willing vehicle, but for the transfers'
        vehicle.ready()
        vehicle.autopilot = true
        vehicle.executorConfig = MissionExecutorConfig.DEFAULT.withVerify(verify)
        vehicle.transferAnswers['upload mission'] = upload
        vehicle.transferAnswers['download mission'] = download

        when:
        launch(hop())
        driveTo(FlightState.UPLOAD)
        for (int i = 0; i < 3 && !executor.completed && executor.state() != FlightState.ARM; i++) {
            step()
        }

        then:
        vehicle.transfers*.toString() == transfers
        error == null ? executor.state() == FlightState.ARM : failure() == "mission hop on vehicle 1: ${error}".toString()
        messages.drop(1) == said(progress)

        where:
        what                                               | verify | upload             | download      || transfers                                               | progress                                                        | error
        'an upload failed, the download finds the mission' | true   | heldButFailed('E') | null          || ['0.0 upload mission: 4 items', '0.0 download mission'] | ['upload verified by download (upload to vehicle 1 failed: E)'] | null
        'an upload failed, the download finds another'     | true   | failed('E')        | held(2, 845f) || ['0.0 upload mission: 4 items', '0.0 download mission'] | []                                                              | 'upload to vehicle 1 failed: E'
        'an upload failed, the download too'               | true   | failed('E')        | failed('D')   || ['0.0 upload mission: 4 items', '0.0 download mission'] | []                                                              | 'upload to vehicle 1 failed: E'
        'an upload done, the vehicle holds another'        | true   | null               | held(2, 845f) || ['0.0 upload mission: 4 items', '0.0 download mission'] | []                                                              | 'the vehicle holds another mission than the one uploaded: item 2 (NAV_WAYPOINT): z sent 840.0, vehicle has 845.0'
        'an upload done, its download failed'              | true   | null               | failed('D')   || ['0.0 upload mission: 4 items', '0.0 download mission'] | []                                                              | 'verifying the upload failed: download from vehicle 1 failed: D'
        'an upload failed, no verification'                | false  | failed('E')        | null          || ['0.0 upload mission: 4 items']                         | []                                                              | 'upload to vehicle 1 failed: E'
        'an upload done, no verification'                  | false  | null               | null          || ['0.0 upload mission: 4 items']                         | []                                                              | null
        outcome = error ?: (progress ? progress[0] : 'ARM follows')
    }

    /** A transfer answer: it fails with "upload to vehicle 1 failed: E" (or download from). */
    static Closure failed(String why) {
        return { FakeFlightVehicle.Transfer t ->
            t.result.complete(new dolphin.mission.transfer.TransferResult(false,
                    "${t.upload ? 'upload to' : 'download from'} vehicle 1 failed: ${why}".toString(), [], 0, 0))
        }
    }

    /** An upload answer: the vehicle holds the items, but the upload fails (its final ACK lost): "upload to vehicle 1 failed: E". */
    static Closure heldButFailed(String why) {
        return { FakeFlightVehicle v, FakeFlightVehicle.Transfer t ->
            v.stored[t.type] = t.items
            failed(why).call(t)
        }
    }

    /** A download answer: the mission uploaded, but item {@code seq} at another height. */
    static Closure held(int seq, float z) {
        return { FakeFlightVehicle.Transfer t ->
            def items = hop().mission().items(HOME).collect {
                it.seq() == seq ? new MissionItem(it.seq(), it.command(), it.frame(), it.param1(), it.param2(), it.param3(), it.param4(),
                        it.x(), it.y(), z, it.autocontinue()) : it
            }
            t.result.complete(new dolphin.mission.transfer.TransferResult(true, null, items, 0, 0))
        }
    }

    def "a fence the vehicle holds differently fails the mission naming the fence; the mission is not uploaded"() {
        given:
        vehicle.ready()
        vehicle.autopilot = true
        def task = MissionDsl.mission {
            name 'hop'
            fence {
                inclusion polygon(HOME.displace(500, 0, 0), HOME.displace(-300, 400, 0), HOME.displace(-300, -400, 0))
            }
            takeOff Position.fromDegrees(40.444233, -7.375234, 840)
        }
        def fence = task.mission().fence().items()
        vehicle.transferAnswers['download fence'] = { FakeFlightVehicle.Transfer t ->
            t.result.complete(new dolphin.mission.transfer.TransferResult(true, null, fence.take(2), 0, 0))
        }

        when:
        launch(task)
        driveTo(FlightState.VERIFY)
        step()

        then:
        failure() == 'mission hop on vehicle 1: the vehicle holds another fence than the one uploaded: the vehicle has 2 items, 3 were sent'
        vehicle.transfers*.toString() == ['0.0 upload fence: 3 items', '0.0 download fence']
    }

    @Unroll
    def "#stage waiting for ever fails just after its deadline (#limit s): '#stage did not finish within its deadline'"() {
        given: 'a vehicle that never ends the transfer, or never answers the command'
        vehicle.ready()
        vehicle.autopilot = true
        vehicle.transferAnswers[waitFor] = { t -> }
        vehicle.answers[waitFor] = { c -> }

        when:
        launch(hop())
        step()
        driveTo(stage)
        double entered = now()
        runTo(entered + limit)

        then:
        !executor.completed

        when:
        runTo(entered + limit + 1)

        then:
        now() == entered + limit + 0.1d
        failure() == "mission hop on vehicle 1: ${stage} did not finish within its deadline".toString()

        where:
        stage        | waitFor            || limit
        FlightState.UPLOAD | 'upload mission'   || 120
        FlightState.VERIFY | 'download mission' || 120
        FlightState.START  | 'DO_SET_MODE AUTO' || 30
    }

    // ---- ARM

    @Unroll
    def "ARM's GUIDED answered #answer: #outcome"() {
        given:
        vehicle.ready()
        vehicle.autopilot = true
        vehicle.answers['DO_SET_MODE GUIDED'] = result

        when:
        launch(hop())
        driveTo(FlightState.ARM)
        step()

        then:
        vehicle.commands*.text == sent
        (error == null) ? executor.state() == FlightState.START : failure() == "mission hop on vehicle 1: ${error}".toString()

        where:
        answer                     | result                       || sent                          | error
        'DENIED'                   | MAV_RESULT.MAV_RESULT_DENIED || ['DO_SET_MODE GUIDED']        | 'vehicle 1 refused GUIDED: DENIED'
        'nothing (mode unchanged)' | NO_ACK                       || ['DO_SET_MODE GUIDED']        | 'vehicle 1 did not answer GUIDED: no COMMAND_ACK after 5 attempt(s)'
        'nothing (mode changed)'   | DONE                         || ['DO_SET_MODE GUIDED', 'ARM'] | null
        outcome = error ?: 'armed'
    }

    @Unroll
    def "ARM refused is sent again every 2 s until the 10 s arm deadline, then the mission fails with #why"() {
        given:
        vehicle.ready()
        vehicle.autopilot = true
        vehicle.executorConfig = MissionExecutorConfig.DEFAULT.withArm(Duration.ofSeconds(10))
        vehicle.answers['ARM'] = MAV_RESULT.MAV_RESULT_FAILED
        texts.each { vehicle.text(it) }

        when:
        launch(hop())
        driveTo(FlightState.ARM)
        step()
        runTo(9.9)

        then:
        !executor.completed
        vehicle.commands.findAll { it.text == 'ARM' }*.time == [0.0d, 2.0d, 4.0d, 6.0d, 8.0d]

        when:
        runTo(11)

        then:
        now() == 10.0d
        vehicle.commands.findAll { it.text == 'ARM' }*.time == [0.0d, 2.0d, 4.0d, 6.0d, 8.0d, 10.0d]
        failure() == "mission hop on vehicle 1: vehicle 1 refused to arm for 10 s: ${text}".toString()
        !messages.contains('mission hop on vehicle 1: armed')

        where:
        why                                     | texts                                                                                   || text
        "the vehicle's last text about arming"  | ['PreArm: Throttle below failsafe', 'Arm: Throttle too high', 'EKF3 IMU0 is using GPS'] || 'Arm: Throttle too high'
        'the last answer, when it said nothing' | []                                                                                      || 'FAILED'
    }

    def "ARM accepted at the third attempt: armed at 4 s; ARM unanswered but the vehicle armed counts too"() {
        given:
        vehicle.ready()
        vehicle.autopilot = true
        int attempts = 0
        vehicle.answers['ARM'] = { c ->
            if (++attempts < 3) {
                vehicle.answer(c, MAV_RESULT.MAV_RESULT_TEMPORARILY_REJECTED)
            } else {
                vehicle.effect(c)
                vehicle.answer(c, NO_ACK)
            }
        }

        when:
        launch(hop())
        driveTo(FlightState.ARM)
        step()
        runTo(5)

        then:
        vehicle.commands.findAll { it.text == 'ARM' }*.time == [0.0d, 2.0d, 4.0d]
        messages.contains('mission hop on vehicle 1: armed')
        executor.state() == FlightState.RUNNING
        vehicle.commands.find { it.text == 'DO_SET_MISSION_CURRENT 1' }.time == 4.1d
    }

    // ---- START

    @Unroll
    def "START's #command answered #answer: #outcome"() {
        given:
        vehicle.ready()
        vehicle.autopilot = true
        vehicle.answers[command] = result
        def task = MissionDsl.mission {
            name 'hop'
            fence {
                inclusion polygon(HOME.displace(500, 0, 0), HOME.displace(-300, 400, 0), HOME.displace(-300, -400, 0))
                enable true
            }
            takeOff Position.fromDegrees(40.444233, -7.375234, 840)
        }

        when:
        launch(task)
        driveTo(FlightState.START)
        step()

        then:
        vehicle.commands*.text.drop(2) == sent
        (error == null) ? executor.state() == FlightState.RUNNING : failure() == "mission hop on vehicle 1: ${error}".toString()

        where:
        command                    | answer                         | result                       || sent                                                                                   | error
        'DO_FENCE_ENABLE 1'        | 'nothing'                      | NO_ACK                       || ['DO_FENCE_ENABLE 1']                                                                  | 'vehicle 1 did not answer MAV_CMD_DO_FENCE_ENABLE 1: no COMMAND_ACK after 5 attempt(s)'
        'DO_SET_MISSION_CURRENT 1' | 'DENIED'                       | MAV_RESULT.MAV_RESULT_DENIED || ['DO_FENCE_ENABLE 1', 'DO_SET_MISSION_CURRENT 1']                                      | 'vehicle 1 refused MAV_CMD_DO_SET_MISSION_CURRENT 1: DENIED'
        'DO_SET_MISSION_CURRENT 1' | 'nothing (item 1 current)'     | DONE                         || ['DO_FENCE_ENABLE 1', 'DO_SET_MISSION_CURRENT 1', 'DO_SET_MODE AUTO', 'MISSION_START'] | null
        'DO_SET_MODE AUTO'         | 'DENIED'                       | MAV_RESULT.MAV_RESULT_DENIED || ['DO_FENCE_ENABLE 1', 'DO_SET_MISSION_CURRENT 1', 'DO_SET_MODE AUTO']                  | 'vehicle 1 refused AUTO: DENIED'
        'DO_SET_MODE AUTO'         | 'nothing (mode changed)'       | DONE                         || ['DO_FENCE_ENABLE 1', 'DO_SET_MISSION_CURRENT 1', 'DO_SET_MODE AUTO', 'MISSION_START'] | null
        'MISSION_START'            | 'nothing (mission not active)' | NO_ACK                       || ['DO_FENCE_ENABLE 1', 'DO_SET_MISSION_CURRENT 1', 'DO_SET_MODE AUTO', 'MISSION_START'] | 'vehicle 1 did not answer MAV_CMD_MISSION_START: no COMMAND_ACK after 5 attempt(s)'
        'MISSION_START'            | 'nothing (mission active)'     | DONE                         || ['DO_FENCE_ENABLE 1', 'DO_SET_MISSION_CURRENT 1', 'DO_SET_MODE AUTO', 'MISSION_START'] | null
        outcome = error ?: 'started'
    }

    // ---- RUNNING

    @Unroll
    def "during the mission, #what: ERROR naming the item and what the vehicle reported; no RTL"() {
        given: 'a copter flying item 2 at 20 m, item 1 reported reached'
        flyingItem2()
        int sent = vehicle.commands.size()

        when:
        change.resolveStrategy = Closure.DELEGATE_FIRST
        change.delegate = vehicle
        change()
        def waiting = runTo(6.9)
        def cs = runTo(10)

        then: 'judged 2 s after the first sign (a text at 5.0 s as it came, a state at the step of 5.1 s), with what the vehicle said; a disarm with no position after it 4 s after'
        waiting == CompletionState.IN_PROGRESS
        cs.error
        now() == at
        failure() == "mission hop on vehicle 1: ${text}".toString()
        executor.state() == FlightState.ERROR
        vehicle.commands.size() == sent
        vehicle.executors == ['flying hop', 'landed hop']

        where:
        what                                     | change                                                                                                                    || at   | text
        'someone switched it to RTL'             | { -> mode('RTL') }                                                                                                        || 7.1d | 'vehicle 1 left AUTO for RTL during item 2 of 4 (NAV_WAYPOINT), before the mission ended: armed, RTL, landed state IN_AIR, 20.0 m above home'
        'a failsafe switched it to BRAKE'        | { -> mode('BRAKE'); text('GCS Failsafe', MAV_SEVERITY.MAV_SEVERITY_WARNING) }                                            || 7.1d | "vehicle 1 left AUTO for BRAKE during item 2 of 4 (NAV_WAYPOINT), before the mission ended, saying 'GCS Failsafe': armed, BRAKE, landed state IN_AIR, 20.0 m above home"
        'the EKF failsafe landed it'             | { -> text('EKF variance: position lost', MAV_SEVERITY.MAV_SEVERITY_CRITICAL); mode('LAND'); text('EKF Failsafe: changed to Land Mode', MAV_SEVERITY.MAV_SEVERITY_CRITICAL) } || 7.0d | "vehicle 1 reported 'EKF variance: position lost', 'EKF Failsafe: changed to Land Mode' during item 2 of 4 (NAV_WAYPOINT): armed, LAND, landed state IN_AIR, 20.0 m above home"
        'a motor failed and it fell'             | { -> text('Potential Thrust Loss (2)', MAV_SEVERITY.MAV_SEVERITY_EMERGENCY); at(0, 0); landedState(MAV_LANDED_STATE.MAV_LANDED_STATE_ON_GROUND) } || 7.0d | "vehicle 1 reported 'Potential Thrust Loss (2)' during item 2 of 4 (NAV_WAYPOINT): armed, AUTO, landed state ON_GROUND, 0.0 m above home"
        'it came down without a word'            | { -> at(0, 0); landedState(MAV_LANDED_STATE.MAV_LANDED_STATE_ON_GROUND) }                                               || 7.1d | 'vehicle 1 is on the ground during item 2 of 4 (NAV_WAYPOINT) with items left: armed, AUTO, landed state ON_GROUND, 0.0 m above home'
        'its fence breached, RTL (fence action)' | { -> text('Polygon fence breached'); mode('RTL') }                                                                        || 7.1d | "vehicle 1 breached its fence during item 2 of 4 (NAV_WAYPOINT) and left AUTO for RTL (its fence action): armed, RTL, landed state IN_AIR, 20.0 m above home, last text 'Polygon fence breached'"
        'it crashed and disarmed'                | { -> text('SIM Hit ground at 12 m/s'); at(0, 0); landedState(MAV_LANDED_STATE.MAV_LANDED_STATE_ON_GROUND); armed(false) } || 9.1d | "vehicle 1 disarmed during item 2 of 4 (NAV_WAYPOINT): disarmed, AUTO, landed state ON_GROUND, 0.0 m above home, last text 'SIM Hit ground at 12 m/s'"
    }

    /** A copter flying item 2 of hop at 20 m from 5 s on, item 1 reported reached. */
    private void flyingItem2(MissionTask task = hop5()) {
        vehicle.ready()
        vehicle.autopilot = true
        launch(task)
        stepUntil(FlightState.RUNNING)
        vehicle.landedState(MAV_LANDED_STATE.MAV_LANDED_STATE_IN_AIR)
        vehicle.at(0, 20)
        vehicle.next(2)
        runTo(5)
    }

    def "a pilot's pause is not an abort: LOITER for 15 s is reported, AUTO again is followed to the end, and the script can tell"() {
        given:
        flyingItem2()
        int sent = vehicle.commands.size()

        when: 'a safety pilot switches to LOITER at 5.1 s and back to AUTO at 20.1 s; the copter resumes item 2'
        vehicle.mode('LOITER')
        def paused = runTo(20)
        vehicle.mode('AUTO')
        runTo(21)

        then: 'no error, the pause and the hand-back said as lines and as vehicle events, nothing sent to the vehicle'
        paused == CompletionState.IN_PROGRESS
        vehicle.commands.size() == sent
        vehicle.events == [
                'TAKEN_OVER taken over: LOITER during item 2 of 4 (NAV_WAYPOINT), mission hop paused until AUTO is back, for 120 s at most',
                'HANDED_BACK back in AUTO after 15 s: item 2 of 4 (NAV_WAYPOINT), mission hop goes on']
        messages.containsAll(said([
                'taken over: LOITER during item 2 of 4 (NAV_WAYPOINT), mission hop paused until AUTO is back, for 120 s at most',
                'back in AUTO after 15 s: item 2 of 4 (NAV_WAYPOINT), mission hop goes on']))

        when: 'the copter flies on and lands'
        vehicle.next(3)
        vehicle.next(4)
        vehicle.landAndDisarm()
        def end = runTo(30)

        then:
        end == CompletionState.DONE
    }

    def "a takeover that is not handed back within the mission's takeover timeout is an error"() {
        given:
        flyingItem2(MissionDsl.mission {
            name 'hop'
            takeoverTimeout 30
            takeOff Position.fromDegrees(40.444233, -7.375234, 840)
            goPos 40.4444, -7.375234, 840
            goPos 40.4446, -7.375234, 840
            landingPoint 40.4446, -7.375234, 820
        })

        when:
        vehicle.mode('POSHOLD')
        def held = runTo(35)
        def cs = runTo(40)

        then: 'the takeover began at 5.1 s; 30 s later it fails'
        held == CompletionState.IN_PROGRESS
        cs.error
        now() == 35.2d
        failure() == 'mission hop on vehicle 1: vehicle 1 taken over: POSHOLD for 30 s during item 2 of 4 (NAV_WAYPOINT),' +
                ' not handed back to AUTO within the takeover timeout of 30 s: armed, POSHOLD, landed state IN_AIR, 20.0 m above home'
    }

    def "a pilot who pauses and then sends the vehicle home ends the mission: RTL during the pause is an error"() {
        given:
        flyingItem2()
        vehicle.mode('LOITER')
        runTo(10)

        when:
        vehicle.mode('RTL')
        def cs = runTo(15)

        then:
        cs.error
        now() == 12.1d
        failure() == 'mission hop on vehicle 1: vehicle 1 left AUTO for RTL during item 2 of 4 (NAV_WAYPOINT), before the mission' +
                ' ended: armed, RTL, landed state IN_AIR, 20.0 m above home'
    }

    def "what must not end a flight: a warning during a long leg, notices, a takeover's own texts"() {
        given:
        flyingItem2()

        when:
        vehicle.text('EKF primary changed:1', MAV_SEVERITY.MAV_SEVERITY_WARNING)
        vehicle.text('Mission: 2 WP', MAV_SEVERITY.MAV_SEVERITY_INFO)
        vehicle.text('EKF3 IMU0 switching to compass 1', MAV_SEVERITY.MAV_SEVERITY_NOTICE)
        def cs = runTo(12)

        then:
        cs == CompletionState.IN_PROGRESS
    }

    def "a reboot in mid-mission (time since boot going back) is an error at once"() {
        given:
        flyingItem2()
        vehicle.state = vehicle.state.withBootTime(300_000)

        when:
        vehicle.state = vehicle.state.withBootTime(2_500)
        def cs = runTo(6)

        then:
        cs.error
        now() == 5.1d
        failure().startsWith('mission hop on vehicle 1: vehicle 1 rebooted during item 2 of 4 (NAV_WAYPOINT): its time since boot went back to 2.5 s')
    }

    def "a vehicle that makes no progress: a warning line, then an error at the mission's stall limit"() {
        given: 'the copter hangs 10 m short of item 2 from 5 s on'
        flyingItem2(MissionDsl.mission {
            name 'hop'
            stallLimit 45
            takeOff Position.fromDegrees(40.444233, -7.375234, 840)
            goPos 40.4446, -7.375234, 840
            goPos 40.4448, -7.375234, 840
            landingPoint 40.4448, -7.375234, 820
        })
        vehicle.at(30, 20)
        runTo(6)

        when: 'it keeps reporting the same position every second'
        (7..50).each { vehicle.at(30, 20); runTo(it) }
        def warned = executor.completionState
        (51..60).each { vehicle.at(30, 20); runTo(it) }
        def cs = executor.completionState

        then: 'warned after 15 s (a third of the limit), failed after 45 s, both saying how far it is'
        warned == CompletionState.IN_PROGRESS
        messages.contains(said(['no progress toward item 2 of 4 (NAV_WAYPOINT): 11 m from it, no closer for 15 s'])[0])
        vehicle.events == ['STALLING no progress toward item 2 of 4 (NAV_WAYPOINT): 11 m from it, no closer for 15 s']
        cs.error
        failure() == 'mission hop on vehicle 1: vehicle 1 stalled: no progress toward item 2 of 4 (NAV_WAYPOINT) for 45 s,' +
                ' 11 m from it (the stall limit): armed, AUTO, landed state IN_AIR, 20.0 m above home'
    }

    def "a vehicle lost during the mission (no contact within its connection timeout): ERROR at the next step, no command sent"() {
        given:
        vehicle.ready()
        vehicle.autopilot = true
        vehicle.node.connectionTimeout = 5
        launch(hop5())
        stepUntil(FlightState.RUNNING)
        vehicle.next(2)
        runTo(5)
        int sent = vehicle.commands.size()

        when:
        vehicle.node.connected = false
        def cs = runTo(6)

        then:
        cs.error
        now() == 5.1d
        cs.message == 'vehicle 1 lost: no contact within its connection timeout of 5 s'
        vehicle.commands.size() == sent
        vehicle.executors == ['flying hop', 'landed hop']
    }

    def "a plane that switches to RTL at its last item but never reports it reached: ERROR once the 3 s grace is over"() {
        given:
        vehicle = new FakeFlightVehicle(clock, '1', VehicleFamily.PLANE)
        vehicle.ready()
        vehicle.autopilot = true
        launch(MissionDsl.mission {
            name 'tour'
            takeOff Position.fromDegrees(40.444233, -7.375234, 870)
            goPos 40.4455, -7.375234, 870
            goPos 40.4455, -7.3737, 870
        })
        stepUntil(FlightState.RUNNING)
        vehicle.landedState(MAV_LANDED_STATE.MAV_LANDED_STATE_IN_AIR)
        vehicle.at(0, 50)
        vehicle.next(2)
        runTo(5)
        vehicle.next(3)
        runTo(10)

        when:
        vehicle.mode('RTL')
        def inGrace = runTo(13)
        def after = runTo(14)

        then: 'first seen at 10.1 s, still within the grace at 13.1 s'
        inGrace == CompletionState.IN_PROGRESS
        after.error
        now() == 13.2d
        failure() == 'mission tour on vehicle 1: vehicle 1 left AUTO for RTL during item 3 of 3 (NAV_WAYPOINT), before the mission ended:' +
                ' armed, RTL, landed state IN_AIR, 50.0 m above home'
    }

    def "MISSION_CURRENT counts as progress only while the mission is active (it also counts items during an upload)"() {
        given:
        vehicle.ready()
        vehicle.autopilot = true
        launch(hop5())
        stepUntil(FlightState.RUNNING)
        vehicle.landedState(MAV_LANDED_STATE.MAV_LANDED_STATE_IN_AIR)
        vehicle.at(0, 20)

        when: 'MISSION_CURRENT 3 not active (an upload in progress elsewhere, say): no progress counted from it'
        vehicle.missionCurrent(3, MISSION_STATE.MISSION_STATE_NOT_STARTED)
        def cs = runTo(2)

        then:
        cs == CompletionState.IN_PROGRESS
        !messages.any { it.contains('reached') }
    }
}
