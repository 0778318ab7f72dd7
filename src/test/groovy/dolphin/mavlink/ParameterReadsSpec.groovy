package dolphin.mavlink

import com.MAVLink.common.msg_param_error
import com.MAVLink.common.msg_param_request_read
import com.MAVLink.common.msg_param_value
import com.MAVLink.enums.MAV_PARAM_ERROR
import dolphin.core.ManualClock
import spock.lang.Specification

/** Parameters read by name on a manual clock: answers, resends, a vehicle that lacks the parameter. */
class ParameterReadsSpec extends Specification {

    static final long SECOND = 1_000_000_000L

    ManualClock clock = new ManualClock()
    List<String> sent = []
    ParameterReads reads = new ParameterReads({ node, msg_param_request_read m -> sent << "${m.target_system} ${m.getParam_Id()} ${m.param_index}".toString() }
            as ParameterReads.Request, SECOND, 3)
    MAVLinkNode node = new MAVLinkNode('1', 'UAV', null, null, null, 1, 1, dolphin.mavlink.Autopilot.ARDUPILOT, VehicleFamily.PLANE, clock)

    static paramValue(String name, float v) {
        def m = new msg_param_value(param_value: v, param_count: 1200, param_index: -1)
        m.setParam_Id(name)
        m
    }

    def "a read asks by name, and its PARAM_VALUE completes it; two reads of one name share the request"() {
        when:
        def cruise = reads.read(node, 'AIRSPEED_CRUISE', 0)
        def again = reads.read(node, 'AIRSPEED_CRUISE', 0)
        reads.onValue(node, paramValue('Q_TRANS_DECEL', 2))

        then: 'another parameter answers nothing'
        sent == ['1 AIRSPEED_CRUISE -1']
        !cruise.done

        when:
        reads.onValue(node, paramValue('AIRSPEED_CRUISE', 25))

        then:
        cruise.get().asDouble == 25
        again.get().asDouble == 25
    }

    def "an unanswered read is sent again after the timeout, and is empty after the last attempt"() {
        when:
        def options = reads.read(node, 'Q_OPTIONS', 0)
        reads.tick(SECOND - 1)

        then:
        sent.size() == 1

        when:
        reads.tick(SECOND)
        reads.tick(2 * SECOND)

        then:
        sent.size() == 3
        !options.done

        when:
        reads.tick(3 * SECOND)

        then:
        sent.size() == 3
        options.get().empty
    }

    def "PARAM_ERROR (the vehicle has no such parameter) and a NaN value make the read empty at once"() {
        given:
        def old = reads.read(node, 'TRIM_ARSPD_CM', 0)
        def nan = reads.read(node, 'Q_ENABLE', 0)
        def error = new msg_param_error(error: (short) MAV_PARAM_ERROR.MAV_PARAM_ERROR_DOES_NOT_EXIST)
        error.setParam_Id('TRIM_ARSPD_CM')

        when:
        reads.onError(node, error)
        reads.onValue(node, paramValue('Q_ENABLE', Float.NaN))

        then:
        old.get().empty
        nan.get().empty
        sent.size() == 2
    }
}
