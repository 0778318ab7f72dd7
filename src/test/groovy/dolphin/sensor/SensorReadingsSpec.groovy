package dolphin.sensor

import com.MAVLink.common.msg_camera_information
import com.MAVLink.common.msg_distance_sensor
import com.MAVLink.standard.msg_global_position_int
import com.MAVLink.common.msg_named_value_float
import com.MAVLink.common.msg_named_value_int
import com.MAVLink.common.msg_vfr_hud
import com.MAVLink.enums.MAV_SENSOR_ORIENTATION
import com.MAVLink.enums.MAV_TYPE
import com.MAVLink.minimal.msg_heartbeat
import dolphin.core.EnvironmentException
import dolphin.core.ManualClock
import dolphin.dsl.DslException
import dolphin.mavlink.MAVLinkCommunications
import dolphin.mavlink.MAVLinkConfig
import dolphin.mavlink.MAVLinkNode
import dolphin.mavlink.VehicleFamily
import dolphin.platform.SensorWords
import java.time.Duration
import spock.lang.Specification

/**
 * Sensor readings as scripts read them, on a manual clock with messages handed to the sensor layer as
 * the communications thread would (no socket, no real time): a reading arrives, ages and goes stale;
 * a sensor never heard; two components sending one name; bad values; a user's sensor classes; telemetry
 * fields and their units; payloads announced by the vehicle.
 */
class SensorReadingsSpec extends Specification {

    ManualClock clock = ManualClock.autoAdvancing()
    MAVLinkCommunications comms = new MAVLinkCommunications(MAVLinkConfig.of('udpin:127.0.0.1:0'), clock)
    MAVLinkNode node = new MAVLinkNode('1', 'UAV', comms, null, null, 1, 1, dolphin.mavlink.Autopilot.ARDUPILOT, VehicleFamily.COPTER, clock)
    SensorService service = SensorService.of(comms)
    SensorWords words = new SensorWords(new dolphin.dsl.ScriptContext(null, null, false), service.&add, service.&declared)

    void send(msg) {
        service.message(node, 1, msg)
    }

    void send(int component, msg) {
        service.message(node, component, msg)
    }

    static nv(String name, float value) {
        def m = new msg_named_value_float(value: value)
        m.setName(name)
        m
    }

    def "a reading is the latest value, until it is older than its sensor's 5 s: then reading it is an error"() {
        when:
        send(nv('SMOKE', 12.5f))
        clock.advance(Duration.ofSeconds(1))
        send(nv('SMOKE', 40f))

        then:
        words.sensor(node, 'SMOKE') == 40d
        words.sensorKnown(node, 'SMOKE')

        when: 'the sensor falls silent'
        clock.advance(Duration.ofMillis(5100))

        then:
        !words.sensorKnown(node, 'SMOKE')

        when:
        words.sensor(node, 'SMOKE')

        then:
        EnvironmentException e = thrown()
        e.message == "sensor: vehicle 1's SMOKE is 5.1 s old, older than its 5 s limit: the sensor stopped reporting" +
                " (sensorKnown(v, 'SMOKE') tests for a current value)"

        expect: 'a script may allow older values, or ask for newer ones'
        words.sensor([maxAge: 10], node, 'SMOKE') == 40d
        !words.sensorKnown([maxAge: 2], node, 'SMOKE')
    }

    def "a sensor never heard is waited for 5 s, then an error that says what the vehicle does send"() {
        given:
        send(nv('TEMP', 21f))
        double start = clock.seconds()

        when:
        words.sensor(node, 'SMOKE')

        then:
        EnvironmentException e = thrown()
        e.message == 'sensor: vehicle 1 has sent no SMOKE in 5 s (it sends TEMP)'
        clock.seconds() - start >= 5
        !words.sensorKnown(node, 'SMOKE')
    }

    def "a first reading that comes while the script waits is the answer"() {
        given:
        clock.schedule(Duration.ofSeconds(2)) { send(nv('SMOKE', 3f)) }

        expect:
        words.sensor(node, 'SMOKE') == 3d
        clock.seconds() >= 2 && clock.seconds() < 2.1
    }

    def "two components of one vehicle sending one name: the script says which"() {
        given:
        send(1, nv('TEMP', 20f))
        send(191, nv('TEMP', 35f))

        when:
        words.sensor(node, 'TEMP')

        then:
        EnvironmentException e = thrown()
        e.message == "sensor: vehicle 1 sends TEMP from components 1 and 191; say which: sensor(v, 'TEMP', component: 191)"

        expect:
        words.sensor([component: 191], node, 'TEMP') == 35d
        words.sensor([component: 1], node, 'TEMP') == 20d
        service.readings(node).named('TEMP')*.component == [1, 191]
    }

    def "NaN and infinite values are refused when read, never used as numbers"() {
        given:
        send(nv('SMOKE', value))

        when:
        words.sensor(node, 'SMOKE')

        then:
        EnvironmentException e = thrown()
        e.message == "sensor: vehicle 1 sent SMOKE = ${value as double} (component 1, NAMED_VALUE_FLOAT): not a number a condition can use"
        !words.sensorKnown(node, 'SMOKE')

        where:
        value << [Float.NaN, Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY]
    }

    def "NAMED_VALUE_INT readings, and a name of all ten characters (no NUL on the wire)"() {
        given:
        def count = new msg_named_value_int(value: 7)
        count.setName('BIRDCOUNT1')
        send(count)

        expect:
        words.sensor(node, 'BIRDCOUNT1') == 7d
    }

    def "a name of over 10 characters no vehicle can send is an error at once, without waiting"() {
        given:
        double start = clock.seconds()

        when:
        words.sensor(node, 'TEMPERATURE')

        then:
        DslException e = thrown()
        e.message == "sensor: 'TEMPERATURE' has 11 characters: NAMED_VALUE_FLOAT names have at most 10, so no vehicle" +
                " can send it (did the sender cut it to 'TEMPERATUR'?)"
        clock.seconds() == start
    }

    def "a malformed name is skipped and logged; the communications go on reading"() {
        given:
        def bad = new msg_named_value_float(value: 1f)
        bad.@name[0] = 0x53
        bad.@name[1] = 0x01
        bad.@name[2] = 0x4d

        when:
        send(bad)
        send(nv('SMOKE', 2f))

        then:
        notThrown(Exception)
        service.readings(node).all()*.name == ['SMOKE']
    }

    def "a sensor class installed through META-INF/services turns DISTANCE_SENSOR into metres, with its own freshness"() {
        expect:
        service.sensors()*.class*.simpleName.contains('DistanceSensor')

        when:
        send(new msg_distance_sensor(current_distance: 245, min_distance: 20, max_distance: 4000,
                orientation: MAV_SENSOR_ORIENTATION.MAV_SENSOR_ROTATION_PITCH_270 as short))

        then:
        words.sensor(node, 'DISTANCE_DOWN') == 2.45d
        service.readings(node).named('DISTANCE_DOWN')[0].unit() == 'm'

        when: 'its freshness is 1 s'
        clock.advance(Duration.ofMillis(1200))

        then:
        !words.sensorKnown(node, 'DISTANCE_DOWN')
        service.declared().classes().contains('DISTANCE_DOWN')
    }

    def "a script's own sensor class, added with useSensor, reads from then on"() {
        given: 'a gas sensor on a companion computer that sends its raw voltage as GAS_RAW'
        def gas = new Sensor() {
            Set messages() { [msg_named_value_float] as Set }

            void read(com.MAVLink.Messages.MAVLinkMessage m, ReadingSink out) {
                def v = m as msg_named_value_float
                if (v.name == 'GAS_RAW') {
                    out.put('CO2', 400 + 1000 * v.value, 'ppm')
                }
            }
        }

        when:
        service.add(gas)
        send(191, nv('GAS_RAW', 0.25f))

        then:
        words.sensor(node, 'CO2') == 650d
        words.sensor(node, 'GAS_RAW') == 0.25d
    }

    def "telemetry reads any field of the vehicle's latest message, in Dolphin's units"() {
        given:
        send(new msg_vfr_hud(groundspeed: 7.5f, airspeed: 8f, heading: 270 as short))
        send(new msg_global_position_int(lat: 404442330, lon: -73752340, alt: 820500, relative_alt: 30250, hdg: 9050, vx: -150))

        expect:
        words.telemetry(node, 'VFR_HUD', 'groundspeed') == 7.5d
        Math.abs(words.telemetry(node, 'GLOBAL_POSITION_INT', 'lat') - 40.444233d) < 1e-9
        words.telemetry(node, 'GLOBAL_POSITION_INT', 'relative_alt') == 30.25d
        words.telemetry(node, 'GLOBAL_POSITION_INT', 'hdg') == 90.5d
        words.telemetry(node, 'GLOBAL_POSITION_INT', 'vx') == -1.5d
        TelemetryField.of('GLOBAL_POSITION_INT', 'hdg').unit() == 'deg'
    }

    def "telemetry names that MAVLink does not define are script errors with what exists"() {
        when:
        words.telemetry(node, message, field)

        then:
        DslException e = thrown()
        e.message == expected

        where:
        message          | field          | expected
        'VFR_HUB'        | 'groundspeed'  | "telemetry: no MAVLink message VFR_HUB; did you mean 'VFR_HUD'?"
        'VFR_HUD'        | 'groundsped'   | "telemetry: VFR_HUD has no field groundsped; did you mean 'groundspeed'? (its fields: airspeed, groundspeed, heading, throttle, alt, climb)"
        'BATTERY_STATUS' | 'voltages'     | "telemetry: BATTERY_STATUS.voltages is an array of 10; name an element, e.g. 'voltages[0]'"
        'BATTERY_STATUS' | 'voltages[10]' | 'telemetry: BATTERY_STATUS.voltages has 10 elements, 0 to 9; got 10'
    }

    def "telemetry of a message the vehicle does not send is an error after 5 s, and a stale one too"() {
        when:
        words.telemetry(node, 'VFR_HUD', 'groundspeed')

        then:
        EnvironmentException e = thrown()
        e.message == 'telemetry: vehicle 1 has sent no VFR_HUD from component 1 in 5 s (is it in its telemetry streams?)'

        when:
        send(new msg_vfr_hud(groundspeed: 3f))
        clock.advance(Duration.ofSeconds(6))
        words.telemetry(node, 'VFR_HUD', 'groundspeed')

        then:
        EnvironmentException stale = thrown()
        stale.message == "telemetry: vehicle 1's last VFR_HUD is 6.0 s old, older than the 5 s limit"
    }

    def "payloads: a camera component's heartbeat, the autopilot's CAMERA_INFORMATION, and the names of readings"() {
        when:
        send(100, new msg_heartbeat(type: MAV_TYPE.MAV_TYPE_CAMERA as short))

        then:
        node.payload.has('camera')
        node.payload.components()[0].parameters() == [component: 100]

        when:
        def info = new msg_camera_information()
        info.vendor_name = ('Dolphin'.bytes.collect { it as short } + [0] * 25) as short[]
        info.model_name = ('SimCam'.bytes.collect { it as short } + [0] * 26) as short[]
        send(1, info)
        send(nv('SMOKE', 0f))

        then:
        words.payloads(node) == ['Camera', 'SMOKE']
        node.payload.components()[0].parameters() == [component: 1, vendor: 'Dolphin', model: 'SimCam']
    }

    def "a fleet file names a vehicle, gives its type, payloads and sensors, and declares the names a script may read"() {
        given:
        def file = File.createTempFile('fleet', '.json')
        file.text = '{"vehicles": [{"sysid": 1, "name": "scout", "type": "UUV", "payloads": ["Sidescan", {"name": "Camera", "model": "A7"}],' +
                ' "sensors": ["SMOKE", "CO2"]}]}'

        when:
        service.useFleet(FleetFile.read(file.toPath()))
        send(nv('SMOKE', 1f))

        then:
        node.name == 'scout'
        node.type == 'UUV'
        words.payloads(node) == ['Sidescan', 'Camera', 'SMOKE', 'CO2']
        node.payload.components()[1].parameters() == [model: 'A7']

        when:
        words.sensor(node, 'SMOKY')

        then:
        DslException e = thrown()
        e.message == "sensor: no sensor 'SMOKY' is declared (declared: CO2, DISTANCE_DOWN, DISTANCE_FWD, SMOKE); did you mean 'SMOKE'?"

        cleanup:
        file.delete()
    }

    def "fleet file mistakes name the file, the vehicle and what was expected"() {
        given:
        def file = File.createTempFile('fleet', '.json')
        file.text = text

        when:
        FleetFile.read(file.toPath())

        then:
        IllegalArgumentException e = thrown()
        expected.endsWith(': ') ? e.message.startsWith("${file}: ${expected}") && e.message.length() > "${file}: ${expected}".length()
                : e.message == "${file}: ${expected}".toString()

        cleanup:
        file.delete()

        where:
        text                                                     | expected
        '{"vehicles": [{"sysid": 0}]}'                           | 'vehicle 1: sysid must be a system id from 1 to 255, got 0'
        '{"vehicles": [{"sysid": 2, "payload": ["Camera"]}]}'    | "vehicle 1: unknown key 'payload' (expected sysid, name, type, payloads, sensors)"
        '{"vehicles": [{"sysid": 2, "payloads": [3]}]}'          | 'vehicle 1 (sysid 2): payloads: expected a name or an object with a name, got 3'
        '{"vehicles": [{"sysid": 2}, {"sysid": 2}]}'             | 'vehicle 2: sysid 2 is given twice'
        '{"fleet": []}'                                          | 'expected {"vehicles": [...]} and nothing else'
        '{"vehicles": [}'                                        | 'not JSON: '
    }
}
