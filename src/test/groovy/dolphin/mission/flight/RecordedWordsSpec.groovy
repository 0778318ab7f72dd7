package dolphin.mission.flight

import com.MAVLink.common.msg_statustext
import com.MAVLink.minimal.msg_heartbeat
import dolphin.mavlink.VehicleFamily
import dolphin.sim.TlogFile
import java.nio.file.Files
import java.nio.file.Path
import spock.lang.Specification
import spock.lang.Unroll

/**
 * What real ArduPilot SITL said while its missions flew (src/test/resources/sitl-recordings): in a
 * flight that went well, no text is a fault; in one that went wrong, the first fault text is the one
 * the vehicle's trouble began with.
 */
class RecordedWordsSpec extends Specification {

    static final Path RECORDINGS = Path.of('src/test/resources/sitl-recordings')

    /** The vehicle's texts from its first HEARTBEAT in AUTO on (or all of them), as VehicleWords would hear them. */
    static List<VehicleWords.Said> saidInAuto(String recording, boolean all = false) {
        List<VehicleWords.Said> said = []
        boolean auto = all
        for (TlogFile.Record r : TlogFile.read(RECORDINGS.resolve(recording + '.tlog'))) {
            def m = r.frame.message()
            if (r.frame.sysid() != 1 || r.frame.compid() != 1 || m == null) {
                continue
            }
            if (m instanceof msg_heartbeat) {
                auto |= dolphin.mavlink.Autopilot.ARDUPILOT.modes(VehicleFamily.of(m.type, m.autopilot)).name(m.custom_mode) == 'AUTO'
            } else if (m instanceof msg_statustext && auto) {
                said << new VehicleWords.Said(m.severity, m.getText(), r.micros * 1000)
            }
        }
        said
    }

    @Unroll
    def "#recording: a flight that went well says nothing the fault rule stops for"() {
        given:
        def said = saidInAuto(recording)

        expect: 'it did speak, and none of it is severe (ArduRover\'s internal error at the start included)'
        !said.empty
        said.findAll { it.severe() }*.text() == []

        where:
        recording << ['copter-first-flight', 'copter-survey', 'copter-every-command', 'copter-fence-breach', 'plane-circuit',
                      'rover-square', 'boat-square', 'copter-fault-pause', 'plane-fault-pause', 'rover-fault-pause']
                .findAll { Files.exists(RECORDINGS.resolve(it + '.tlog')) }
    }

    def "ArduRover's internal error as its mission starts is CRITICAL, and no fault"() {
        expect:
        saidInAuto('rover-square', true).any { it.text().startsWith('Internal Errors') && it.severity() == 2 && !it.severe() }
    }

    @Unroll
    def "#recording: the first fault text is #first"() {
        expect:
        saidInAuto(recording).find { it.severe() }?.text() == first

        where:
        recording            | first
        'copter-fault-motor' | 'EKF3 lane switch 1'
        'copter-fault-gps'   | 'EKF3 lane switch 1'
        'rover-fault-gps'    | 'EKF variance'
    }
}
