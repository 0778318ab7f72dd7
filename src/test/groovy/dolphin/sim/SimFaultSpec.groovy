package dolphin.sim

import spock.lang.Specification

/** How a fault to inject is written (KIND[=ARGS]@SECONDS[:SYSID]) and which vehicles can have it (docs/mavlink.md, "Faults"). */
class SimFaultSpec extends Specification {

    def "'#text' is #kind with #args, #seconds s after arming, for vehicle #sysid (0: all), and reads back as #written"() {
        when:
        def fault = SimFault.parse(text)

        then:
        fault.kind() == kind
        fault.args() == args
        fault.afterArmingSeconds() == seconds
        fault.sysid() == sysid
        fault.toString() == written
        SimFault.parse(written) == fault

        where:
        text                     || kind               | args             | seconds | sysid | written
        'motor@60'               || FaultKind.MOTOR    | []               | 60      | 0     | 'motor@60'
        'motor=2@60.5:3'         || FaultKind.MOTOR    | ['2']            | 60.5    | 3     | 'motor=2@60.5:3'
        'GPS@0'                  || FaultKind.GPS      | []               | 0       | 0     | 'gps@0'
        'takeover=15@90'         || FaultKind.TAKEOVER | ['15']           | 90      | 0     | 'takeover=15@90'
        'takeover=15, Loiter@90' || FaultKind.TAKEOVER | ['15', 'loiter'] | 90      | 0     | 'takeover=15,loiter@90'
        'stall@120:255'          || FaultKind.STALL    | []               | 120     | 255   | 'stall@120:255'
        'stall=30@120'           || FaultKind.STALL    | ['30']           | 120     | 0     | 'stall=30@120'
        'reboot@45:1'            || FaultKind.REBOOT   | []               | 45      | 1     | 'reboot@45:1'
        'outage=12.5@30'         || FaultKind.OUTAGE   | ['12.5']         | 30      | 0     | 'outage=12.5@30'
    }

    def "'#text' is refused, saying what was expected"() {
        when:
        SimFault.parse(text)

        then:
        def e = thrown(IllegalArgumentException)
        e.message == message

        where:
        text                  || message
        'motor'               || "'motor': expected KIND[=ARGS]@SECONDS[:SYSID], e.g. motor@60:1 or takeover=15,loiter@90"
        'motor@60@70'         || "'motor@60@70': expected KIND[=ARGS]@SECONDS[:SYSID], e.g. motor@60:1 or takeover=15,loiter@90"
        'lightning@60'        || "unknown fault 'lightning': expected motor, gps, takeover, stall, reboot, outage"
        'motor@soon'          || "'soon' is not a number of seconds, 0 or more"
        'motor@-5'            || "'-5' is not a number of seconds, 0 or more"
        'motor@NaN'           || "'NaN' is not a number of seconds, 0 or more"
        'motor@60:0'          || "'0' is not a system id in 1..255"
        'motor@60:two'        || "'two' is not a system id in 1..255"
        'motor@60:1:2'        || "'motor@60:1:2': expected one :SYSID after @SECONDS"
        'motor=0@60'          || "'0' is not a motor number, 1 or more"
        'motor=1,2@60'        || 'motor=1,2: expected motor[=N]'
        'gps=1@60'            || 'gps=1: expected gps'
        'takeover@60'         || 'takeover: expected takeover=SECONDS[,MODE]'
        'takeover=x@60'       || "'x' is not a number of seconds, 0 or more"
        'takeover=1,a,b@60'   || 'takeover=1,a,b: expected takeover=SECONDS[,MODE]'
        'stall=Infinity@60'   || "'infinity' is not a number of seconds, 0 or more"
        'reboot=now@60'       || 'reboot=now: expected reboot'
        'outage@60'           || 'outage: expected outage=SECONDS'
    }

    def "a fault the vehicles cannot have is refused for them, saying why"() {
        when:
        SimFault.parse(text).checkFor(kind)

        then:
        def e = thrown(IllegalArgumentException)
        e.message.startsWith(message)

        where:
        text                     | kind              || message
        'motor@60'               | VehicleKind.ROVER || 'motor is not simulated on a rover, only on copter, plane'
        'motor@60'               | VehicleKind.SUB   || 'motor is not simulated on a sub, only on copter, plane'
        'gps@60'                 | VehicleKind.PLANE || 'gps is not simulated on a plane, only on copter, rover, boat, heli'
        'motor=5@60'             | VehicleKind.COPTER || 'motor 5: ArduCopter has 4 motors'
        'motor=2@60'             | VehicleKind.PLANE || 'motor 2: ArduPlane has 1 motor'
        'takeover=10,hover@60'   | VehicleKind.COPTER || "ArduCopter has no mode 'hover': expected one of"
        'takeover=10,auto@60'    | VehicleKind.ROVER || 'a takeover hands AUTO back, so its mode must be another one'
    }

    def "each vehicle kind has the faults its family's row gives it"() {
        expect:
        ['motor@1', 'gps@1', 'takeover=5@1', 'stall@1', 'reboot@1', 'outage=5@1'].findAll { text ->
            try {
                SimFault.parse(text).checkFor(kind)
                true
            } catch (IllegalArgumentException ignored) {
                false
            }
        }*.replaceAll(/[=@].*/, '') == faults

        where:
        kind               || faults
        VehicleKind.COPTER || ['motor', 'gps', 'takeover', 'stall', 'reboot', 'outage']
        VehicleKind.PLANE  || ['motor', 'takeover', 'stall', 'reboot', 'outage']
        VehicleKind.ROVER  || ['gps', 'takeover', 'stall', 'reboot', 'outage']
        VehicleKind.BOAT   || ['gps', 'takeover', 'stall', 'reboot', 'outage']
        VehicleKind.SUB    || ['takeover', 'stall', 'reboot', 'outage']
        VehicleKind.QUADPLANE || ['takeover', 'stall', 'reboot', 'outage']
        VehicleKind.HELI   || ['gps', 'takeover', 'stall', 'reboot', 'outage']
    }

    def "a fault for a system id happens to that vehicle only; without one, to every vehicle"() {
        expect:
        SimFault.parse('gps@10:2').appliesTo(2)
        !SimFault.parse('gps@10:2').appliesTo(1)
        (1..255).every { SimFault.parse('gps@10').appliesTo(it) }
    }

    def "made in code, a fault is checked as a written one is"() {
        when:
        new SimFault(FaultKind.OUTAGE, [], 10, 0)

        then:
        thrown(IllegalArgumentException)

        when:
        new SimFault(FaultKind.GPS, [], Double.POSITIVE_INFINITY, 0)

        then:
        thrown(IllegalArgumentException)

        expect:
        SimOptions.DEFAULT.withFault(new SimFault(FaultKind.REBOOT, [], 10, 1)).faults() == [SimFault.parse('reboot@10:1')]
    }
}
