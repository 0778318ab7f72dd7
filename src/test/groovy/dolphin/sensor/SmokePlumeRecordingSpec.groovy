package dolphin.sensor

import com.MAVLink.common.msg_named_value_float
import com.MAVLink.standard.msg_global_position_int
import dolphin.core.ManualClock
import dolphin.core.Position
import dolphin.mavlink.MAVLinkCommunications
import dolphin.mavlink.MAVLinkConfig
import dolphin.mavlink.MAVLinkNode
import dolphin.mavlink.VehicleFamily
import dolphin.platform.SensorWords
import dolphin.sim.TlogFile
import java.nio.file.Path
import java.time.Duration
import spock.lang.Shared
import spock.lang.Specification

/**
 * ArduCopter SITL with smoke-plume.lua and a servo camera, as recorded (sitl-recordings/README.md),
 * replayed into the sensor layer at the recorded times on a manual clock: what the words read is what
 * ArduPilot sent, the readings stay current between two of the script's messages, and the camera is
 * known from the autopilot's CAMERA_INFORMATION.
 */
class SmokePlumeRecordingSpec extends Specification {

    static final Position CENTRE = Position.fromDegrees(40.4461, -7.3752, 0)

    @Shared
    List<TlogFile.Record> records = TlogFile.read(Path.of(SmokePlumeRecordingSpec.getResource('/sitl-recordings/copter-smoke-plume.tlog').toURI()))

    ManualClock clock = new ManualClock()
    MAVLinkCommunications comms = new MAVLinkCommunications(MAVLinkConfig.of('udpin:127.0.0.1:0'), clock)
    MAVLinkNode node = new MAVLinkNode('1', 'UAV', comms, null, null, 1, 1, dolphin.mavlink.Autopilot.ARDUPILOT, VehicleFamily.COPTER, clock)
    SensorService service = SensorService.of(comms)
    SensorWords words = new SensorWords(new dolphin.dsl.ScriptContext(null, null, false), service.&add, service.&declared)

    def "every SMOKE the Lua script sent is read as sent, from component 1, and is the plume's value where the copter was"() {
        given:
        List<Double> read = []
        List<Double> expected = []
        Position last = null
        long start = records[0].micros

        when:
        for (record in records.findAll { it.frame.sysid() == 1 }) {
            clock.advance(Duration.ofNanos((record.micros - start) * 1000 - clock.nanoTime()))
            service.message(node, record.frame.compid(), record.frame.message())
            def m = record.frame.message()
            if (m instanceof msg_global_position_int && m.lat != 0) {
                last = Position.fromDegrees(m.lat * 1e-7, m.lon * 1e-7, 0)
            } else if (m instanceof msg_named_value_float && m.name == 'SMOKE') {
                read << words.sensor(node, 'SMOKE')
                expected << (last == null ? Double.NaN : Math.max(0, 100 * (1 - last.distanceTo(CENTRE) / 60)))
                assert words.sensorKnown(node, 'SMOKE')
            }
        }

        then: 'the 348 readings, 0 at home, up to 99.8 over the centre'
        read.size() == 348
        read.first() == 0d
        read.max() > 99.5
        service.readings(node).named('SMOKE')*.component == [1]

        and: 'each is the plume at the last position the copter reported (up to 0.25 s and 3.4 points older)'
        [read, expected].transpose().every { r, e -> Double.isNaN(e) || Math.abs(r - e) < 4 }
    }

    def "the servo camera answers with CAMERA_INFORMATION from the autopilot: the vehicle carries a Camera, no Gimbal"() {
        when:
        records.findAll { it.frame.sysid() == 1 }.each { service.message(node, it.frame.compid(), it.frame.message()) }

        then:
        node.payload.names() == ['Camera', 'SMOKE']
        node.payload.components()[0].parameters() == [component: 1, vendor: '', model: '']
    }
}
