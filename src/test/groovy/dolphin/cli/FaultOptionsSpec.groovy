package dolphin.cli

import dolphin.sim.SimFault
import spock.lang.Specification
import spock.lang.Timeout

/** {@code dolphin sim --fault} and {@code dolphin run --sim-fault}: faults injected into the simulated fleet at a time. */
@Timeout(60)
class FaultOptionsSpec extends Specification {

    static final String EXAMPLE = RunCommandSpec.EXAMPLE

    def "dolphin sim --fault, repeated, gives the fleet its faults in order"() {
        when:
        def config = SimCommandSpec.parsed('--count', '2', '--fault', 'motor=2@60:1', '--fault', 'takeover=15,loiter@90')
                .fleetConfig()

        then:
        config.options().faults() == [SimFault.parse('motor=2@60:1'), SimFault.parse('takeover=15,loiter@90')]
    }

    def "dolphin sim says which faults it will inject, as they are written"() {
        given:
        def out = new StringWriter()

        when:
        int code = Main.commandLine(new PrintWriter(out), new PrintWriter(new StringWriter()))
                .execute('sim', '--fault', 'GPS@60', '--fault', 'stall=20@90.5:1', '--duration', '0')

        then:
        code == 0
        out.toString().contains('faults, at seconds after a vehicle first arms: gps@60, stall=20@90.5:1')
    }

    def "dolphin run --sim-fault gives the in-process fleet its faults; without them it has none"() {
        given:
        def port = new InetSocketAddress('127.0.0.1', 14560)
        def command = RunCommandSpec.parsed(EXAMPLE, '--sim', '2', '--sim-type', 'rover', '--sim-fault', 'gps@30:2',
                '--sim-fault', 'outage=10@45')
        def plain = RunCommandSpec.parsed(EXAMPLE, '--sim', '2')

        expect:
        command.fleetConfig([port], command.faultModel()).options().faults() == [SimFault.parse('gps@30:2'), SimFault.parse('outage=10@45')]
        plain.fleetConfig([port], plain.faultModel()).options().faults().isEmpty()
    }

    def "a bad fault is a usage error naming the option and saying what was expected"() {
        given:
        def out = new StringWriter()
        def err = new StringWriter()

        when: 'a short --duration for dolphin sim, so a value wrongly accepted ends the run with 0 instead of never'
        int code = Main.commandLine(new PrintWriter(out), new PrintWriter(err)).execute(args as String[])

        then:
        code == 2
        err.toString().contains(message)

        where:
        args                                                                   | message
        ['sim', '--fault', 'motor', '--duration', '0']                         | "Invalid value for option '--fault' (KIND[=ARGS]@SECONDS[:SYSID]): 'motor': expected KIND[=ARGS]@SECONDS[:SYSID], e.g. motor@60:1"
        ['sim', '--fault', 'hail@60', '--duration', '0']                       | "Invalid value for option '--fault' (KIND[=ARGS]@SECONDS[:SYSID]): unknown fault 'hail': expected motor, gps, takeover, stall, reboot, outage"
        ['sim', '--fault', 'takeover@60', '--duration', '0']                   | "Invalid value for option '--fault' (KIND[=ARGS]@SECONDS[:SYSID]): takeover: expected takeover=SECONDS[,MODE]"
        ['sim', '--fault', 'motor@-1', '--duration', '0']                      | "Invalid value for option '--fault' (KIND[=ARGS]@SECONDS[:SYSID]): '-1' is not a number of seconds, 0 or more"
        ['sim', '--type', 'rover', '--fault', 'motor@60', '--duration', '0']   | "--fault 'motor@60': motor is not simulated on a rover, only on copter, plane"
        ['sim', '--type', 'sub', '--fault', 'gps@60', '--duration', '0']       | "--fault 'gps@60': gps is not simulated on a sub, only on copter, rover, boat"
        ['sim', '--fault', 'takeover=5,hover@60', '--duration', '0']           | "--fault 'takeover=5,hover@60': ArduCopter has no mode 'hover'"
        ['sim', '--count', '2', '--fault', 'reboot@60:3', '--duration', '0']   | "--fault 'reboot@60:3': no vehicle with system id 3 in the fleet (1..2)"
        ['run', EXAMPLE, '--sim-fault', 'gps@60']                              | '--sim-fault needs --sim: it sets up the simulated fleet'
        ['run', EXAMPLE, '--sim', '1', '--sim-fault', 'gps']                   | "Invalid value for option '--sim-fault' (KIND[=ARGS]@SECONDS[:SYSID]): 'gps': expected KIND[=ARGS]@SECONDS[:SYSID]"
        ['run', EXAMPLE, '--sim', '1', '--sim-fault', 'motor=9@60']            | "--sim-fault 'motor=9@60': motor 9: ArduCopter has 4 motors"
        ['run', EXAMPLE, '--sim', '1', '--sim-fault', 'stall@60:2']            | "--sim-fault 'stall@60:2': no vehicle with system id 2 in the fleet (1..1)"
    }
}
