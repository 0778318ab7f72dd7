package dolphin.mavlink

import com.MAVLink.common.msg_sys_status
import com.MAVLink.enums.MAV_AUTOPILOT
import com.MAVLink.enums.MAV_TYPE
import com.MAVLink.minimal.msg_heartbeat
import dolphin.dsl.ScriptResult
import dolphin.mavlink.codec.FrameWriter
import spock.lang.AutoCleanup
import spock.lang.Specification

/** Scripts on the MAVLink platform against simulated vehicles: the words of design §7. */
class MavlinkScriptSpec extends Specification {

    @AutoCleanup
    FleetHarness h = new FleetHarness()
    List<String> messages = new java.util.concurrent.CopyOnWriteArrayList()

    ScriptResult run(String script) {
        h.run(script, 'mavlink.dolphin', messages)
    }

    def "a script picks two vehicles and prints their battery and position (AMSL)"() {
        given:
        def fleet = h.fleet(2)
        fleet.vehicle(2).setBattery(73)

        when:
        def result = run('''
            v1 = pick { type 'UAV'; timeout 20 }
            v2 = pick { type 'UAV'; timeout 20 }
            [v1, v2].each { v -> message "vehicle ${v}: battery ${battery(v)} at ${position(v)}" }
        ''')

        then:
        result.outcome == ScriptResult.Outcome.COMPLETED
        messages.find { it.startsWith('vehicle { 1 }: battery 1.0 at (40.444233°, -7.375234°, 820.') }
        messages.find { it.startsWith('vehicle { 2 }: battery 0.73 at (40.444233°, -7.375116°, 820.') }
    }

    def "a region pick uses positions above mean sea level"() {
        given: 'three copters 10 m apart in a line to the east of the fleet home, at 820 m'
        def fleet = h.fleet(3)
        def third = fleet.vehicle(3).position()
        h.eventually { assert h.comms.nodes().every { it.position != null } }

        when:
        def result = run("""
            near = pick { region location(${third.latitudeDegrees()}, ${third.longitudeDegrees()}, 820) ^ 3; timeout 5 }
            message "near: \${near}"
            high = pick { region location(${third.latitudeDegrees()}, ${third.longitudeDegrees()}, 900) ^ 30 }
        """)

        then: 'the 820 m region holds vehicle 3 only; one 80 m higher holds none'
        messages.contains('near: { 3 }')
        result.outcome == ScriptResult.Outcome.HALTED
        result.message.contains('could not find 1 free vehicle')
    }

    def "a condition on the battery reacts when the vehicle reports the change"() {
        given:
        def fleet = h.fleet(1)
        h.eventually { assert h.node('1')?.state()?.systemStatus() != null }
        def engineDone = Thread.start {
            h.eventually(20) { assert messages.contains('waiting') }
            fleet.vehicle(1).setBattery(40)
        }

        when:
        def result = run('''
            v = pick { timeout 10 }
            message 'waiting'
            execute v: waitFor { battery(v) < 0.5 } then action { message "low: ${battery(v)}" }
        ''')
        engineDone.join(20000)

        then:
        result.outcome == ScriptResult.Outcome.COMPLETED
        messages.contains('low: 0.4')
    }

    def "battery(v) and position(v) wait 5 s for a vehicle's first report, then fail clearly; so does a missing battery monitor"() {
        given: 'two fake vehicles: one sends heartbeats only, one reports battery_remaining -1'
        def socket = new DatagramSocket()
        def quiet = new FrameWriter(9, 1)
        def unknown = new FrameWriter(10, 1)
        def hb = new msg_heartbeat(type: MAV_TYPE.MAV_TYPE_QUADROTOR, autopilot: MAV_AUTOPILOT.MAV_AUTOPILOT_ARDUPILOTMEGA)
        def to = new InetSocketAddress('127.0.0.1', h.port())
        def beat = Thread.start {
            while (!Thread.currentThread().interrupted) {
                [quiet.write(hb), unknown.write(hb), unknown.write(new msg_sys_status(battery_remaining: -1 as byte))].each {
                    socket.send(new DatagramPacket(it, it.length, to))
                }
                try { Thread.sleep(20) } catch (InterruptedException e) { break }
            }
        }
        h.eventually { assert h.node('9') != null && h.node('10')?.state()?.systemStatus() != null }

        when:
        def noStatus = run("v = pick { id '9' }\nbattery(v)")
        def noMonitor = run("v = pick { id '10' }\nbattery(v)")
        double before = h.clock.seconds()
        def noPosition = run("v = pick { id '9' }\nposition(v)")
        double waited = h.clock.seconds() - before

        then:
        noStatus.outcome == ScriptResult.Outcome.SCRIPT_ERROR
        noStatus.error.line == 2
        noStatus.error.message.contains('vehicle 9 has sent no SYS_STATUS in 5 s')
        noMonitor.error.message.contains('vehicle 10 reports no battery level')
        noPosition.outcome == ScriptResult.Outcome.SCRIPT_ERROR
        noPosition.error.message.contains('vehicle 9 has not reported a position yet')
        waited >= 5

        cleanup:
        beat?.interrupt()
        socket?.close()
    }

    def "sendMessage sends a raw MAVLink message from the script to each vehicle of a set"() {
        given:
        def fleet = h.fleet(2)
        h.eventually { assert h.comms.nodes().size() == 2 }
        int before = fleet.vehicle(2).commandsHandled()

        when:
        def result = run('''
            v = pick { id '2' }
            sendMessage v, new msg_command_long(target_system: 2, target_component: 1, command: MAV_CMD.MAV_CMD_BATTERY_RESET,
                                                param1: 255, param2: 55)
        ''')

        then:
        result.outcome == ScriptResult.Outcome.COMPLETED
        messages.contains('sent COMMAND_LONG to vehicle 2')
        // Discovery's telemetry requests may still be arriving, so count at least our one command.
        h.eventually { assert fleet.vehicle(2).battery() == 55d && fleet.vehicle(2).commandsHandled() >= before + 1 }
    }

    def "a lost vehicle cannot be picked"() {
        given:
        def fleet = h.fleet(2)
        h.eventually { assert h.comms.nodes().size() == 2 }
        h.comms.nodes().each { it.connectionTimeout = 5 }
        fleet.vehicle(1).silent = true
        h.eventually { assert !h.node('1').connected }

        when:
        run('v = pick { count 1 }\nmessage "picked ${v}"\nw = pick { count 1 }')

        then:
        messages.contains('picked { 2 }')
        messages.any { it.contains('halted: pick: could not find 1 free vehicle') }
    }
}
