package dolphin.cli

import dolphin.mavlink.Autopilot
import dolphin.mission.flight.MissionExecutorConfig
import dolphin.mavlink.LinkTimeouts
import dolphin.mission.transfer.MissionTransferConfig
import dolphin.mission.transfer.TransferPath
import dolphin.core.Position
import dolphin.platform.DiveSilenceSpec
import dolphin.sim.FaultModel
import dolphin.sim.SimFleet
import dolphin.sim.VehicleKind
import java.time.Duration
import picocli.CommandLine
import spock.lang.Specification
import spock.lang.Timeout

@Timeout(60)
class RunCommandSpec extends Specification {

    static final String EXAMPLE = 'dsl-examples/battery-and-position.dolphin'

    static Map dolphin(String... args) {
        def out = new StringWriter()
        def err = new StringWriter()
        int code = Main.commandLine(new PrintWriter(out), new PrintWriter(err)).execute(args)
        [code: code, out: out.toString(), err: err.toString()]
    }

    /** The command with its options parsed, not run: no links, no fleet. */
    static RunCommand parsed(String... args) {
        def command = new RunCommand()
        new CommandLine(command).parseArgs(args)
        command
    }

    /**
     * A free UDP port below Linux's ephemeral range (from 32768): a port the system handed out and took
     * back could be handed at once to the simulated fleet's own udpout socket (CI: "Address already in use").
     */
    static int freePort() {
        int start = 20000 + new Random().nextInt(12000)
        (start..<32768).find { int port ->
            try {
                new DatagramSocket(port).close()
                true
            } catch (SocketException ignored) {
                false
            }
        } as int
    }

    def "the example runs against the in-process simulated fleet"() {
        when:
        def r = dolphin('run', EXAMPLE, '--sim', '2', '--speedup', '5')

        then:
        r.code == 0
        r.out =~ /vehicle \{ 1 \}: battery 100 %, position \(40\.444233°, -7\.375234°, 820\.000\)/
        r.out =~ /vehicle \{ 2 \}: battery 100 %, position \(40\.444233°, -7\.375116°, 820\.000\)/
        r.out.contains("${EXAMPLE}: completed")
    }

    def "a simulated #type at --sim-home is picked as a #dolphinType and starts there, at the surface"() {
        given:
        def script = File.createTempFile('where', '.dolphin')
        script.deleteOnExit()
        script.text = """v = pick { type '${dolphinType}'; timeout 30.seconds }
message "${dolphinType}: position \${position(v)}"
release v
"""

        when:
        def r = dolphin('run', script.path, '--sim', '1', '--sim-type', type, '--sim-home', '38.43462,-8.86118', '--speedup', '5')

        then:
        r.code == 0
        r.out.contains("${dolphinType}: position (38.434620°, -8.861180°, 0.000)")

        where:
        type   || dolphinType
        'sub'  || 'UUV'
        'boat' || 'USV'
    }

    def "--sim-home and --sim-dive-silence make the in-process fleet's home and its subs' dive silence"() {
        given:
        def port = new InetSocketAddress('127.0.0.1', 14560)
        def command = parsed(EXAMPLE, '--sim', '2', '--sim-type', 'sub', '--sim-home', '38.43462,-8.86118', '--sim-dive-silence', '4.5')
        def plain = parsed(EXAMPLE, '--sim', '2', '--sim-type', 'ardusub')

        when:
        def config = command.fleetConfig([port], command.faultModel())
        def defaults = plain.fleetConfig([port], plain.faultModel())

        then:
        config.kind() == VehicleKind.SUB
        config.home() == Position.fromDegrees(38.43462, -8.86118, 0)
        config.options().diveSilenceMetres() == 4.5d

        and: 'without them, the report base and subs always heard'
        defaults.kind() == VehicleKind.SUB
        defaults.home() == SimFleet.Config.DEFAULT_HOME
        defaults.options().autopilot() == Autopilot.ARDUPILOT
        defaults.options().diveSilenceMetres() == Double.POSITIVE_INFINITY
        defaults.options().ftp()
    }

    def "--sim-no-ftp makes the in-process fleet's vehicles without MAVLink FTP"() {
        given:
        def command = parsed(EXAMPLE, '--sim', '1', '--sim-no-ftp')

        expect:
        !command.fleetConfig([new InetSocketAddress('127.0.0.1', 14560)], command.faultModel()).options().ftp()
    }

    def "the example runs over a lossy simulated link"() {
        when:
        def r = dolphin('run', EXAMPLE, '--sim', '2', '--speedup', '5', '--loss', '0.1', '--fault-seed', '3')

        then:
        r.code == 0
        r.out.contains('vehicle { 1 }: battery 100 %')
        r.out.contains('vehicle { 2 }: battery 100 %')
        r.out.contains("${EXAMPLE}: completed")
    }

    def "with --sim the link-fault options make the in-process fleet's fault model"() {
        given:
        def command = parsed(EXAMPLE, '--sim', '2', '--loss', '0.1', '--duplicate', '0.05', '--delay', '200', '--reorder', '50',
                '--fault-seed', '3')
        def port = new InetSocketAddress('127.0.0.1', 14560)

        when:
        def config = command.fleetConfig([port], command.faultModel())

        then:
        config.faults() == new FaultModel(0.1, 0.05, 0.2, 0.05, 3)
        config.count() == 2
        config.gcs() == [port]
    }

    def "without link-fault options the in-process fleet's link is perfect"() {
        expect:
        parsed(EXAMPLE, '--sim', '1').faultModel() == FaultModel.NONE
    }

    def "the retry options set the command attempts and the mission transfers' timeouts, give-up and path"() {
        when:
        def command = parsed(EXAMPLE, '--command-attempts', '9', '--transfer-min-timeout', '100', '--transfer-max-timeout', '2500',
                '--transfer-give-up', '12.5', '--transfer-path', 'items')

        then:
        command.mavlinkConfig().commandAttempts() == 9
        command.transferConfig() == new MissionTransferConfig(
                new LinkTimeouts(Duration.ofMillis(100), Duration.ofMillis(2500), Duration.ofMillis(12500)), TransferPath.ITEMS)
        parsed(EXAMPLE, '--transfer-path', 'ftp').transferConfig().path() == TransferPath.FTP
    }

    def "without retry options commands and transfers keep their defaults"() {
        when:
        def command = parsed(EXAMPLE)

        then:
        command.mavlinkConfig().commandAttempts() == 5
        command.transferConfig() == MissionTransferConfig.DEFAULT
        MissionTransferConfig.DEFAULT == new MissionTransferConfig(
                new LinkTimeouts(Duration.ofMillis(50), Duration.ofMillis(1500), Duration.ofSeconds(10)), TransferPath.AUTO)
        command.executorConfig() == MissionExecutorConfig.DEFAULT
    }

    def "--ready-timeout is how long a mission waits for its vehicle to become ready"() {
        expect:
        parsed(EXAMPLE, '--ready-timeout', '600').executorConfig().prepare() == Duration.ofMinutes(10)
        MissionExecutorConfig.DEFAULT.prepare() == Duration.ofMinutes(3)
    }

    def "--stall-limit and --takeover-timeout set how long a flight may make no progress and be held by someone else"() {
        when:
        def c = parsed(EXAMPLE, '--stall-limit', '30', '--takeover-timeout', '300').executorConfig()

        then: 'the warning comes at a third of the stall limit'
        c.stallLimit() == Duration.ofSeconds(30)
        c.stallWarning() == Duration.ofSeconds(10)
        c.takeoverTimeout() == Duration.ofMinutes(5)
        MissionExecutorConfig.DEFAULT.stallLimit() == Duration.ofSeconds(60)
        MissionExecutorConfig.DEFAULT.stallWarning() == Duration.ofSeconds(20)
        MissionExecutorConfig.DEFAULT.takeoverTimeout() == Duration.ofSeconds(120)
    }

    def "dolphin run talks to vehicles that dolphin sim started separately"() {
        given:
        int port = freePort()
        def sim = Thread.start {
            dolphin('sim', '--count', '2', '--link', "udpout:127.0.0.1:${port}", '--speedup', '5', '--duration', '60')
        }

        when:
        def r = dolphin('run', EXAMPLE, '--link', "udpin:127.0.0.1:${port}")

        then:
        r.code == 0
        r.out.contains('vehicle { 1 }: battery 100 %')
        r.out.contains('vehicle { 2 }: battery 100 %')

        cleanup:
        sim?.interrupt()
    }

    def "--status plain: a line per vehicle when its mode, arming or task changes"() {
        when:
        def r = dolphin('run', 'dsl-examples/first-flight.dolphin', '--sim', '1', '--speedup', '10', '--status', 'plain')

        then:
        r.code == 0
        def lines = r.out.readLines()
        // a task's start shows its vehicle as it was then, however fast the run; the first AUTO
        // sample may precede the first MISSION_CURRENT of the flight
        int started = lines.findIndexOf { it ==~ /\[ *[\d.]+ s\] task first flight started on vehicle 1/ }
        started >= 0
        lines[started + 1] ==~ /\[ *[\d.]+ s\] vehicle 1: STABILIZE, disarmed, battery (100 %|\?), altitude 0.0 m, task first flight running/
        int flying = lines.findIndexOf { it ==~ /\[ *[\d.]+ s\] vehicle 1: AUTO, armed, battery \d+ %, altitude [\d.]+ m(, item \d of 4)?, task first flight running/ }
        flying > started
        int completed = lines.findIndexOf { it ==~ /\[ *[\d.]+ s\] task first flight completed on vehicle 1: DONE/ }
        lines[completed + 1] ==~ /\[ *[\d.]+ s\] vehicle 1: \w+, disarmed, .*task first flight done/
        completed > flying
        !r.out.contains('\033[')
    }

    def "a sub out of contact while it dives: a line when contact is lost, its status line, and a line when contact is back"() {
        given: 'the dive of more than a minute under 1 m of water, where the simulated sub sends and hears nothing'
        def script = File.createTempFile('dive', '.dolphin')
        script.text = DiveSilenceSpec.script('10.minutes')

        when:
        def r = dolphin('run', script.path, '--sim', '1', '--sim-type', 'sub', '--sim-home', '38.43462,-8.86118',
                '--sim-dive-silence', '1', '--speedup', '10', '--status', 'plain')

        then:
        r.code == 0
        def lines = r.out.readLines()
        int lost = lines.findIndexOf { it ==~ /\[ *[\d.]+ s\] vehicle 1: no contact for 3 s/ }
        int silent = lines.findIndexOf { it ==~ /\[ *[\d.]+ s\] vehicle 1: no contact \d+ s, last seen AUTO, armed, .*task deep running/ }
        int again = lines.findIndexOf { it ==~ /\[ *[\d.]+ s\] vehicle 1: contact again after \d+ s/ }
        lost >= 0 && lost < silent && silent < again
        (lines[again] =~ /after (\d+) s/)[0][1] as int >= 60
        lines.count { it.contains('vehicle 1: no contact for') } == 1
        r.out.contains('task deep completed on vehicle 1: DONE')
        r.out.contains('back at 0 m')

        cleanup:
        script?.delete()
    }

    def "--status live: a table of the vehicles redrawn in place below the lines"() {
        when:
        def r = dolphin('run', EXAMPLE, '--sim', '2', '--speedup', '5', '--status', 'live')

        then:
        r.code == 0
        r.out.contains(VehicleStatus.HEADER)
        r.out.contains('\033[3F\033[J')
        r.out.readLines().any { it ==~ /2 +\w+ +disarmed +100 % +0\.0 m -.*/ }
        r.out.contains("${EXAMPLE}: completed")
    }

    def "a script with a mistake is refused before it picks a vehicle: file:line:column and exit 1"() {
        given:
        def script = File.createTempFile('bad', '.dolphin')
        script.text = 'v = pick { timeout 5 }\ntakeoff v\n'

        when:
        def r = dolphin('run', script.path, '--sim', '1', '--speedup', '5')

        then:
        r.code == 1
        r.err.contains("${script.path}:2:1: unknown command 'takeoff'; did you mean 'takeOff'? It can only be used inside mission { }")
        !r.out.contains('picked')

        cleanup:
        script?.delete()
    }

    def "--web serves the live view of the run and prints its address"() {
        when:
        def r = dolphin('run', EXAMPLE, '--sim', '2', '--speedup', '5', '--web', '0')

        then:
        r.code == 0
        r.out =~ /web view: http:\/\/127\.0\.0\.1:\d+\//
        r.out.contains("${EXAMPLE}: completed")
    }

    def "--web on a port in use: the run goes on without the view, and says why"() {
        given:
        def taken = new ServerSocket(0, 1, InetAddress.getByName('127.0.0.1'))

        when:
        def r = dolphin('run', EXAMPLE, '--sim', '2', '--speedup', '5', '--web', "${taken.localPort}")

        then:
        r.code == 0
        r.err.contains("dolphin run: web view not started: --web 127.0.0.1:${taken.localPort}: port ${taken.localPort} is in use "
                + 'on 127.0.0.1 (another program, or another dolphin run, listens there); the run goes on without it')
        !r.out.contains('web view:')
        r.out.contains("${EXAMPLE}: completed")

        cleanup:
        taken.close()
    }

    def "bad command lines are usage errors: a message and exit 2"() {
        when:
        def r = dolphin(args as String[])

        then:
        r.code == 2
        r.err.contains(message)

        where:
        args                                                       | message
        ['run', EXAMPLE, '--frobnicate']                           | "Unknown option: '--frobnicate'"
        ['run']                                                    | "Missing required parameter: 'SCRIPT'"
        ['run', 'no/such.dolphin']                                 | 'cannot read no/such.dolphin: no such file'
        ['run', EXAMPLE, '--link', 'udpin:localhost']              | "bad connection string 'udpin:localhost': expected HOST:PORT"
        ['run', EXAMPLE, '--link', 'carrier-pigeon:1']             | "unknown link kind 'carrier-pigeon'"
        ['run', EXAMPLE, '--link', 'udpin:0.0.0.0:99999']          | 'the port must be between 0 and 65535'
        ['run', EXAMPLE, '--speedup', '10']                        | '--speedup needs --sim'
        ['run', EXAMPLE, '--sim', '1', '--sim-type', 'hovercraft'] | "unknown vehicle type 'hovercraft': expected copter, plane, rover, boat, sub, quadplane or heli"
        ['run', EXAMPLE, '--sim-home', '38.43462,-8.86118']        | '--sim-home needs --sim: it sets up the simulated fleet'
        ['run', EXAMPLE, '--sim-dive-silence', '5']                | '--sim-dive-silence needs --sim'
        ['run', EXAMPLE, '--sim-no-ftp']                           | '--sim-no-ftp needs --sim: it sets up the simulated fleet'
        ['run', EXAMPLE, '--sim-autopilot', 'px4']                 | '--sim-autopilot needs --sim: it sets up the simulated fleet'
        ['run', EXAMPLE, '--sim', '1', '--sim-autopilot', 'inav']  | "unknown autopilot 'inav': expected ardupilot or px4"
        ['run', EXAMPLE, '--sim', '1', '--sim-autopilot', 'px4', '--sim-type', 'rover'] | '--sim-autopilot px4 simulates copter, plane, quadplane only, got --sim-type rover'
        ['run', EXAMPLE, '--sim', '1', '--sim-home', '38.43462']   | "home '38.43462': expected LAT,LON[,ALT], e.g. 38.43462,-8.86118"
        ['run', EXAMPLE, '--sim', '1', '--sim-home', '38.4,-8.8,deep'] | "home '38.4,-8.8,deep': expected LAT,LON[,ALT]"
        ['run', EXAMPLE, '--sim', '1', '--sim-home', '38.4,-188']  | "home '38.4,-188': latitude must be in [-90, 90], longitude in [-180, 180]"
        ['run', EXAMPLE, '--sim', '1', '--sim-dive-silence', '5']  | '--sim-dive-silence needs --sim-type sub: only a sub dives, got --sim-type copter'
        ['run', EXAMPLE, '--sim', '1', '--sim-type', 'sub', '--sim-dive-silence', '-2'] | '--sim-dive-silence must be a depth in metres, 0 or more, got -2.0'
        ['run', EXAMPLE, '--sim', '1', '--sim-type', 'sub', '--sim-dive-silence', 'deep'] | "Invalid value for option '--sim-dive-silence': 'deep' is not a double"
        ['run', EXAMPLE, '--sim', '600', '--link', 'udpin:127.0.0.1:0'] | '--sim 600: 600 vehicles from system id 1 need at least 3 links'
        ['run', EXAMPLE, '--status', 'fancy']                      | "Invalid value for option '--status'"
        ['run', EXAMPLE, '--forward', 'udpout:nowhere']            | "bad connection string 'udpout:nowhere': expected HOST:PORT"
        ['run', EXAMPLE, '--web', 'eighty']                        | "'eighty': expected [HOST:]PORT, e.g. 8080 or 0.0.0.0:8080"
        ['run', EXAMPLE, '--web', '127.0.0.1:99999']               | 'the port must be between 0 and 65535, got 99999'
        ['run', EXAMPLE, '--web-tiles', 'https://t.example/{z}/{x}/{y}.png'] | '--web-tiles needs --web'
        ['run', EXAMPLE, '--web', '0', '--web-tiles', 'https://t.example/tiles.png'] | 'expected a tile URL with {z}, {x} and {y}'
        ['run', EXAMPLE, '--sim-sensor', 'SMOKE:plume:40,-7,60,100']                   | '--sim-sensor needs --sim: only simulated vehicles carry simulated sensors and cameras'
        ['run', EXAMPLE, '--sim-camera', '1']                                          | '--sim-camera needs --sim'
        ['run', EXAMPLE, '--sim-config', 'fleet.json']                                 | '--sim-config needs --sim'
        ['run', EXAMPLE, '--sim', '1', '--sim-sensor', 'SMOKE:plume:40,-7,60,100@2']   | "--sim-sensor 'SMOKE:plume:40,-7,60,100@2': no vehicle with system id 2 in the fleet (1..1)"
        ['run', EXAMPLE, '--sim', '1', '--sim-camera', '1+2']                          | "--sim-camera '1+2': no vehicle with system id 2 in the fleet (1..1)"
        ['run', EXAMPLE, '--sim', '1', '--sim-config', 'no/such.json']                 | '--sim-config no/such.json: no such file'
        ['sim', '--count', '0']                                    | '--count must be at least 1'
        ['sim', '--count', '300']                                  | '300 vehicles from system id 1 need at least 2 links'
        ['sim', '--link', 'udpin:0.0.0.0:14559']                   | '--link for sim must be udpout:HOST:PORT'
        ['sim', '--home', '95,0,0']                                | 'latitude must be in [-90, 90]'
        ['sim', '--dive-silence', '5']                             | '--dive-silence needs --type sub: only a sub dives, got --type copter'
        ['sim', '--autopilot', 'PX4', '--type', 'heli']            | '--autopilot px4 simulates copter, plane, quadplane only, got --type heli'
        ['sim', '--type', 'sub', '--dive-silence', '-0.5']         | '--dive-silence must be a depth in metres, 0 or more, got -0.5'
        ['run', EXAMPLE, '--loss', '0.1']                          | '--loss needs --sim: link faults are simulated'
        ['run', EXAMPLE, '--delay', '100']                         | '--delay needs --sim'
        ['run', EXAMPLE, '--fault-seed', '3']                      | '--fault-seed needs --sim'
        ['run', EXAMPLE, '--sim', '1', '--loss', '1.5']            | '--loss must be a probability from 0 to 1, got 1.5'
        ['run', EXAMPLE, '--sim', '1', '--reorder', '-20']         | '--reorder must be a number of milliseconds, 0 or more, got -20'
        ['run', EXAMPLE, '--command-attempts', '0']                | '--command-attempts must be at least 1, got 0'
        ['run', EXAMPLE, '--command-attempts', 'many']             | "Invalid value for option '--command-attempts': 'many' is not an int"
        ['run', EXAMPLE, '--transfer-min-timeout', '0']            | '--transfer-min-timeout must be a positive number of milliseconds, got 0'
        ['run', EXAMPLE, '--transfer-min-timeout', '-50']          | '--transfer-min-timeout must be a positive number of milliseconds, got -50'
        ['run', EXAMPLE, '--transfer-max-timeout', '1.5s']         | "Invalid value for option '--transfer-max-timeout': '1.5s' is not a long"
        ['run', EXAMPLE, '--transfer-max-timeout', '20']           | '--transfer-max-timeout (20 ms) must be at least --transfer-min-timeout (50 ms)'
        ['run', EXAMPLE, '--transfer-give-up', '1']                | '--transfer-give-up (1.0 s) must be at least --transfer-max-timeout (1500 ms)'
        ['run', EXAMPLE, '--transfer-give-up', 'NaN']              | '--transfer-give-up (NaN s) must be at least --transfer-max-timeout (1500 ms)'
        ['run', EXAMPLE, '--transfer-path', 'tcp']                 | "Invalid value for option '--transfer-path': 'tcp' is not auto, ftp or items"
        ['run', EXAMPLE, '--ready-timeout', '0']                   | '--ready-timeout must be a positive number of seconds, got 0'
        ['run', EXAMPLE, '--stall-limit', '-5']                    | '--stall-limit must be a positive number of seconds, got -5'
        ['run', EXAMPLE, '--takeover-timeout', '0']                | '--takeover-timeout must be a positive number of seconds, got 0'
    }
}
