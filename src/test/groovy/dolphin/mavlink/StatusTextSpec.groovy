package dolphin.mavlink

import com.MAVLink.common.msg_statustext
import spock.lang.Specification

class StatusTextSpec extends Specification {

    static said(String text) {
        def m = new msg_statustext()
        m.setText(text)
        m
    }

    def "PX4's trailing tab goes; ArduPilot's words, and the spaces between them, stay"() {
        expect:
        StatusText.of(said('Geofence violation for waypoint 3\t')) == 'Geofence violation for waypoint 3'
        StatusText.of(said('PreArm: Need Position Estimate')) == 'PreArm: Need Position Estimate'
        StatusText.of(said('SIM Hit ground at 0.500000 m/s')) == 'SIM Hit ground at 0.500000 m/s'
    }
}
