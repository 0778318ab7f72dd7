package dolphin.platform

import com.MAVLink.common.msg_named_value_float
import dolphin.core.Position
import dolphin.dsl.ScriptResult
import dolphin.mavlink.FleetHarness
import dolphin.mavlink.codec.FrameWriter
import dolphin.sim.FaultModel
import dolphin.sim.LinearField
import dolphin.sim.SimEquipment
import dolphin.sim.SimFleet
import dolphin.sim.SimOptions
import dolphin.sim.SimSensor
import dolphin.sim.SysidSet
import dolphin.sim.VehicleKind
import java.util.concurrent.CopyOnWriteArrayList
import spock.lang.AutoCleanup
import spock.lang.Specification

/**
 * Sensor words in scripts, over UDP on loopback: the simulated fleet's readings in waitFor, a task's
 * condition and during; a companion computer (component 191) sending readings of its own, a malformed
 * one among them, without taking over where replies to the vehicle go.
 */
class SensorScriptSpec extends Specification {

    @AutoCleanup
    FleetHarness h = new FleetHarness()
    List<String> messages = new CopyOnWriteArrayList()

    ScriptResult run(String script) {
        h.run(script, 'sensors.dolphin', messages)
    }

    def "readings in waitFor, in a task's condition and under during: the vehicle at rest reads 25 degC"() {
        given: 'TEMP rises 1 degC per 100 m to the north of a point 1 km south of home, where it is 15'
        Position south = SimFleet.Config.DEFAULT_HOME.displace(-1000, 0, 0)
        h.fleet(1, VehicleKind.COPTER, 1, SimOptions.DEFAULT, FaultModel.NONE, null,
                new SimEquipment([new SimSensor('TEMP', new LinearField(south, 15, 0.01, 0), SysidSet.ALL)], SysidSet.NONE))

        when:
        def result = run('''
            v = pick { payload 'TEMP'; timeout 20 }
            execute v: waitFor { sensor(v, 'TEMP') > 20 } then action { message "warm: ${sensor(v, 'TEMP')}" }
            cut = execute v: (idle(60) / { sensorKnown(v, 'TEMP') && sensor(v, 'TEMP') > 24 })
            message "cut: ${cut}"
            bounded = execute v: (during 2 run (waitFor { sensorKnown(v, 'NOSUCH') } then idle(1)))
            message "during: ${bounded}"
        ''')

        then:
        result.outcome == ScriptResult.Outcome.COMPLETED
        Math.abs((messages.find { it.startsWith('warm: ') } - 'warm: ').toDouble() - 25) < 0.01
        messages.find { it.startsWith('cut: ') }
        messages.find { it.startsWith('during: ') }
    }

    def "a companion computer's readings are read by component; a malformed one is skipped; replies still go to the autopilot"() {
        given: 'the sensor layer attached, as dolphin run attaches it before its links open'
        dolphin.sensor.SensorService.of(h.comms)
        h.fleet(1)
        h.eventually { assert h.node('1')?.state()?.heartbeat() != null }
        def autopilotAddress = h.node('1').address
        def companion = new DatagramSocket()
        def writer = new FrameWriter(1, 191)
        def send = { msg_named_value_float m ->
            byte[] frame = writer.write(m)
            companion.send(new DatagramPacket(frame, frame.length, new InetSocketAddress('127.0.0.1', h.port())))
        }
        def bad = new msg_named_value_float(value: 1f)
        bad.@name[0] = 0x43
        bad.@name[1] = 0x07
        def co2 = new msg_named_value_float(value: 612f)
        co2.setName('CO2')

        when:
        send(bad)
        send(co2)
        def result = run('''
            v = pick { timeout 20 }
            message "co2 ${sensor(v, 'CO2', component: 191)}, payloads ${payloads(v)}"
        ''')

        then:
        result.outcome == ScriptResult.Outcome.COMPLETED
        messages.contains('co2 612.0, payloads [CO2]')
        h.node('1').address == autopilotAddress

        cleanup:
        companion?.close()
    }
}
