package dolphin.cli

import dolphin.core.Position
import dolphin.mavlink.Autopilot
import dolphin.sim.FaultModel
import dolphin.sim.VehicleKind
import picocli.CommandLine
import spock.lang.Specification
import spock.lang.Timeout

@Timeout(60)
class SimCommandSpec extends Specification {

    /** The command with its options parsed, not run: no fleet, no sockets. */
    static SimCommand parsed(String... args) {
        def command = new SimCommand()
        new CommandLine(command).parseArgs(args)
        command
    }

    def "the link-fault options make the fleet's fault model, delays in milliseconds of clock time"() {
        when:
        def config = parsed('--loss', '0.1', '--duplicate', '0.05', '--delay', '200', '--reorder', '50', '--fault-seed', '3')
                .fleetConfig()

        then:
        config.faults() == new FaultModel(0.1, 0.05, 0.2, 0.05, 3)
    }

    def "without link-fault options the fleet's link is perfect"() {
        expect:
        parsed().fleetConfig().faults() == FaultModel.NONE
        parsed('--fault-seed', '9').fleetConfig().faults().none()
    }

    def "--type sub with --home and --dive-silence: subs off Comporta at sea level, silent below 8 m; boats are ArduRover's"() {
        when:
        def config = parsed('--type', 'sub', '--home', '38.43462,-8.86118', '--dive-silence', '8').fleetConfig()

        then:
        config.kind() == VehicleKind.SUB
        config.home() == Position.fromDegrees(38.43462, -8.86118, 0)
        config.options().diveSilenceMetres() == 8d
        parsed('--type', 'boat').fleetConfig().kind() == VehicleKind.BOAT
        parsed('--home', '40.444233,-7.375234,820').fleetConfig().home() == Position.fromDegrees(40.444233, -7.375234, 820)
    }

    def "--autopilot px4 makes PX4 vehicles of the types PX4 is simulated for; by default they run ArduPilot"() {
        expect:
        parsed('--autopilot', 'px4', '--type', 'quadplane').fleetConfig().options().autopilot() == Autopilot.PX4
        parsed('--autopilot', 'px4').fleetConfig().kind() == VehicleKind.COPTER
        parsed().fleetConfig().options().autopilot() == Autopilot.ARDUPILOT
    }

    def "--no-ftp makes vehicles without MAVLink FTP; by default they have it"() {
        expect:
        !parsed('--no-ftp').fleetConfig().options().ftp()
        parsed().fleetConfig().options().ftp()
    }

    def "a bad link-fault value is a usage error naming the option and the value"() {
        given:
        def out = new StringWriter()
        def err = new StringWriter()

        when: 'a short --duration, so a value wrongly accepted ends the run with 0 instead of never'
        int code = Main.commandLine(new PrintWriter(out), new PrintWriter(err))
                .execute(['sim', *args, '--duration', '0'] as String[])

        then:
        code == 2
        err.toString().contains(message)

        where:
        args                       | message
        ['--loss', '1.5']          | '--loss must be a probability from 0 to 1, got 1.5'
        ['--loss', 'NaN']          | '--loss must be a probability from 0 to 1, got NaN'
        ['--loss', 'lots']         | "Invalid value for option '--loss': 'lots' is not a double"
        ['--duplicate', '-0.1']    | '--duplicate must be a probability from 0 to 1, got -0.1'
        ['--delay', '-5']          | '--delay must be a number of milliseconds, 0 or more, got -5'
        ['--delay', '1s']          | "Invalid value for option '--delay': '1s' is not a long"
        ['--reorder', '-1']        | '--reorder must be a number of milliseconds, 0 or more, got -1'
        ['--fault-seed', 'random'] | "Invalid value for option '--fault-seed': 'random' is not a long"
    }
}
