package dolphin.sim

import com.MAVLink.common.msg_named_value_float
import com.MAVLink.enums.COPTER_MODE
import com.MAVLink.enums.MAV_RESULT
import dolphin.core.Position
import spock.lang.Specification

import static dolphin.sim.SimDriver.HOME

/** Simulated vehicles read their sensors where they are and send NAMED_VALUE_FLOAT at 2 Hz; fake clock, no sockets. */
class SimSensorsSpec extends Specification {

    static final PlumeField SMOKE = new PlumeField(HOME, 60, 100, 0)

    static SimDriver vehicle(int sysid, SimEquipment equipment, Position home = HOME, long boot = 0) {
        new SimDriver(VehicleKind.COPTER, SimOptions.DEFAULT, home, boot, equipment, sysid)
    }

    static List<msg_named_value_float> readings(SimDriver d, int from, String name = null) {
        d.since(from, msg_named_value_float).findAll { name == null || it.name == name }
    }

    def "a vehicle sends each of its readings every half second of clock time, time_boot_ms counting from its boot"() {
        given: 'booted at 7 s of clock time'
        def d = vehicle(1, new SimEquipment([new SimSensor('SMOKE', SMOKE)], SysidSet.NONE), HOME, 7_000_000_000L)
        d.run(1)
        int from = d.mark()

        when:
        d.run(10)

        then:
        def smoke = readings(d, from)
        smoke.size() == 20
        smoke*.name.unique() == ['SMOKE']
        smoke*.time_boot_ms == (3..22).collect { it * 500L }
        smoke.every { Math.abs(it.value - 100) < 1e-3 }
    }

    def "disarmed or armed, the readings go on; a silent vehicle sends none"() {
        given:
        def d = vehicle(1, new SimEquipment([new SimSensor('SMOKE', SMOKE)], SysidSet.NONE))

        when:
        int disarmed = d.mark()
        d.run(2)
        d.setMode(COPTER_MODE.COPTER_MODE_GUIDED)
        def arming = d.arm()
        int armed = d.mark()
        d.run(2)
        d.vehicle.setSilent(true)
        int silent = d.mark()
        d.run(2)

        then:
        arming.result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.vehicle.armed()
        readings(d, disarmed).size() >= 4
        readings(d, armed).size() == 4
        readings(d, silent).empty
    }

    def "each vehicle reads where it is"() {
        given:
        def equipment = new SimEquipment([new SimSensor('SMOKE', SMOKE)], SysidSet.NONE)
        def near = vehicle(1, equipment, HOME.displace(30, 0, 0))
        def far = vehicle(2, equipment, HOME.displace(0, 90, 0))

        when:
        near.run(1)
        far.run(1)

        then:
        readings(near, 0).every { Math.abs(it.value - 50) < 1e-3 }
        readings(far, 0).every { it.value == 0 }
        !readings(far, 0).empty
    }

    def "fields of one name add up into one reading; other names are readings of their own"() {
        given: 'a plume on a background that rises 0.01 per metre to the north, and a temperature'
        def equipment = new SimEquipment([
                new SimSensor('SMOKE', SMOKE),
                new SimSensor('SMOKE', new LinearField(HOME, 2, 0.01, 0)),
                new SimSensor('TEMP', new LinearField(HOME, 15, -0.1, 180))], SysidSet.NONE)
        def d = vehicle(1, equipment, HOME.displace(30, 0, 0))

        when: 'the first tick'
        d.tick()

        then: 'one SMOKE of 50 + 2.3 and one TEMP of 15 + 3 per period'
        def sent = readings(d, 0)
        sent*.name == ['SMOKE', 'TEMP']
        Math.abs(sent[0].value - 52.3) < 1e-3
        Math.abs(sent[1].value - 18) < 1e-3
    }

    def "only the vehicles that carry a sensor send it; without sensors a vehicle sends no readings"() {
        given:
        def equipment = new SimEquipment([
                new SimSensor('SMOKE', SMOKE, SysidSet.of([1, 2])),
                new SimSensor('GAS', new LinearField(HOME, 1, 0, 0), SysidSet.of([2]))], SysidSet.NONE)
        def one = vehicle(1, equipment)
        def two = vehicle(2, equipment)
        def three = vehicle(3, equipment)

        when:
        [one, two, three]*.run(2)

        then:
        readings(one, 0)*.name.unique() == ['SMOKE']
        readings(two, 0)*.name.unique().sort() == ['GAS', 'SMOKE']
        readings(two, 0, 'GAS').size() == 5
        readings(three, 0).empty
        readings(vehicle(1, SimEquipment.NONE).tap { run(2) }, 0).empty
    }
}
