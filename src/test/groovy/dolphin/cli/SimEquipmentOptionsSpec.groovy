package dolphin.cli

import dolphin.core.Position
import dolphin.sim.LinearField
import dolphin.sim.PlumeField
import dolphin.sim.SimSensor
import dolphin.sim.SysidSet
import spock.lang.Specification
import spock.lang.TempDir
import spock.lang.Timeout

import java.nio.file.Path

import static dolphin.cli.RunCommandSpec.dolphin

/**
 * The simulated fleet's sensors and cameras from the command line and a JSON file, for
 * {@code dolphin sim} (--sensor, --camera, --config) and {@code dolphin run --sim}
 * (--sim-sensor, --sim-camera, --sim-config): parsed, not run, so no fleet and no sockets.
 */
@Timeout(60)
class SimEquipmentOptionsSpec extends Specification {

    static final String EXAMPLE = RunCommandSpec.EXAMPLE
    static final Position CENTRE = Position.fromDegrees(40.4461, -7.3752, 0)

    @TempDir
    Path dir

    Path json(String text) {
        def file = dir.resolve('fleet.json')
        java.nio.file.Files.writeString(file, text)
        file
    }

    def "dolphin sim: --sensor, a plume and a linear field, on chosen vehicles or all; --camera on some"() {
        when:
        def equipment = SimCommandSpec.parsed('--count', '3', '--sensor', 'SMOKE:plume:40.4461,-7.3752,60,100@1+2',
                '--sensor', 'TEMP:field:40.4461,-7.3752,15,0.01,90', '--sensor', 'GAS:plume:40.4461,-7.3752,30,5,0.5@3',
                '--camera', '2+3').fleetConfig().equipment()

        then:
        equipment.sensors() == [
                new SimSensor('SMOKE', new PlumeField(CENTRE, 60, 100, 0), SysidSet.of([1, 2])),
                new SimSensor('TEMP', new LinearField(CENTRE, 15, 0.01, 90), SysidSet.ALL),
                new SimSensor('GAS', new PlumeField(CENTRE, 30, 5, 0.5), SysidSet.of([3]))]
        equipment.cameras() == SysidSet.of([2, 3])
    }

    def "without the options the vehicles carry nothing; --camera all puts one on each"() {
        expect:
        SimCommandSpec.parsed().fleetConfig().equipment().sensors().empty
        !SimCommandSpec.parsed().fleetConfig().equipment().cameras().contains(1)
        SimCommandSpec.parsed('--count', '4', '--camera', 'all').fleetConfig().equipment().cameras() == SysidSet.ALL
    }

    def "dolphin run --sim: the same with --sim-sensor and --sim-camera"() {
        given:
        def command = RunCommandSpec.parsed(EXAMPLE, '--sim', '2', '--sim-sensor', 'SMOKE:plume:40.4461,-7.3752,60,100@2',
                '--sim-camera', '1')

        when:
        def equipment = command.fleetConfig([new InetSocketAddress('127.0.0.1', 14560)], command.faultModel()).equipment()

        then:
        equipment.sensors() == [new SimSensor('SMOKE', new PlumeField(CENTRE, 60, 100, 0), SysidSet.of([2]))]
        equipment.cameras() == SysidSet.of([1])
    }

    def "a JSON file says the same, and adds to the options"() {
        given:
        def file = json('''{"sensors": [
                {"name": "SMOKE", "plume": {"lat": 40.4461, "lon": -7.3752, "radius": 60, "peak": 100}, "vehicles": [1]},
                {"name": "TEMP", "field": {"lat": 40.4461, "lon": -7.3752, "base": 15, "gradient": 0.01, "bearing": 90}}],
                "cameras": [2]}''')

        when:
        def sim = SimCommandSpec.parsed('--count', '3', '--config', file.toString(), '--sensor', 'GAS:field:40.4461,-7.3752,1,0,0',
                '--camera', '3').fleetConfig().equipment()
        def run = RunCommandSpec.parsed(EXAMPLE, '--sim', '2', '--sim-config', file.toString())
                .fleetConfig([new InetSocketAddress('127.0.0.1', 14560)], dolphin.sim.FaultModel.NONE).equipment()

        then:
        sim.sensors() == [
                new SimSensor('SMOKE', new PlumeField(CENTRE, 60, 100, 0), SysidSet.of([1])),
                new SimSensor('TEMP', new LinearField(CENTRE, 15, 0.01, 90), SysidSet.ALL),
                new SimSensor('GAS', new LinearField(CENTRE, 1, 0, 0), SysidSet.ALL)]
        sim.cameras() == SysidSet.of([2, 3])
        run.sensors()*.name() == ['SMOKE', 'TEMP']
        run.cameras() == SysidSet.of([2])
    }

    def "a plume's background and cameras: all in the file"() {
        when:
        def equipment = SimCommandSpec.parsed('--config', json('''{"sensors": [{"name": "CO2",
                "plume": {"lat": 40.4461, "lon": -7.3752, "radius": 60, "peak": 100, "background": 400}}], "cameras": "all"}''')
                .toString()).fleetConfig().equipment()

        then:
        equipment.sensors() == [new SimSensor('CO2', new PlumeField(CENTRE, 60, 100, 400))]
        equipment.cameras() == SysidSet.ALL
    }

    def "a bad --sensor or --camera is a usage error naming the option, the entry and what was expected"() {
        when: 'a short --duration, so a value wrongly accepted ends the run with 0 instead of never'
        def r = dolphin(['sim', '--count', '2', *args, '--duration', '0'] as String[])

        then:
        r.code == 2
        r.err.contains(message)

        where:
        args                                                         | message
        ['--sensor', 'TEMPERATURE:field:40,-7,15,0.01,90']           | "--sensor 'TEMPERATURE:field:40,-7,15,0.01,90': a sensor name must be 1 to 10 printable ASCII characters"
        ['--sensor', 'SMOKE:plume:40,-7,-60,100']                    | "--sensor 'SMOKE:plume:40,-7,-60,100': the radius must be a positive number of metres, got -60.0"
        ['--sensor', 'SMOKE:plume:40,-7,60,NaN']                     | "--sensor 'SMOKE:plume:40,-7,60,NaN': the peak must be a finite number, got NaN"
        ['--sensor', 'TEMP:field:40,-7,15,NaN,90']                   | "--sensor 'TEMP:field:40,-7,15,NaN,90': the gradient must be a finite number, got NaN"
        ['--sensor', 'SMOKE:plume:40,-7,60,100@3']                   | "--sensor 'SMOKE:plume:40,-7,60,100@3': no vehicle with system id 3 in the fleet (1..2)"
        ['--sensor', 'SMOKE:plume:40,-7,60,100@1+x']                 | "--sensor 'SMOKE:plume:40,-7,60,100@1+x': 'x' is not a system id: expected SYSID[+SYSID...] or all"
        ['--sensor', 'SMOKE:plume:40,-7,60,100@0']                   | "--sensor 'SMOKE:plume:40,-7,60,100@0': a system id must lie in 1..255, got 0"
        ['--sensor', 'SMOKE:plume:40,-7,60']                         | "--sensor 'SMOKE:plume:40,-7,60': a plume takes LAT,LON,RADIUS,PEAK[,BACKGROUND], got 3 number(s)"
        ['--sensor', 'TEMP:field:40,-7,15,0.01']                     | "--sensor 'TEMP:field:40,-7,15,0.01': a field takes LAT,LON,BASE,GRADIENT,BEARING, got 4 number(s)"
        ['--sensor', 'SMOKE:cloud:40,-7,60,100']                     | "--sensor 'SMOKE:cloud:40,-7,60,100': unknown kind 'cloud': expected plume or field"
        ['--sensor', 'SMOKE:plume:40,-7,sixty,100']                  | "--sensor 'SMOKE:plume:40,-7,sixty,100': 'sixty' is not a number"
        ['--sensor', 'SMOKE']                                        | "--sensor 'SMOKE': expected NAME:plume:LAT,LON,RADIUS,PEAK[,BACKGROUND] or NAME:field:LAT,LON,BASE,GRADIENT,BEARING"
        ['--sensor', 'SMOKE:plume:95,-7,60,100']                     | "--sensor 'SMOKE:plume:95,-7,60,100': the centre must have a latitude in [-90, 90]"
        ['--camera', '5']                                            | "--camera '5': no vehicle with system id 5 in the fleet (1..2)"
        ['--camera', 'two']                                          | "--camera 'two': 'two' is not a system id: expected SYSID[+SYSID...] or all"
    }

    def "a bad --config file is a usage error naming the option, the file, the entry and what was expected"() {
        given:
        def file = json(text)

        when:
        def r = dolphin('sim', '--count', '2', '--config', file.toString(), '--duration', '0')

        then:
        r.code == 2
        r.err.contains("--config ${file}: ${message}")

        where:
        text                                                                                      | message
        '{"sensor": []}'                                                                          | 'the file: unknown key "sensor"; expected sensors, cameras'
        '{"sensors": [{"name": "SMOKE", "plume": {"lat": 40, "lon": -7, "radius": 60, "peak": 100}, "vehicle": [1]}]}' | 'sensors[0]: a sensor: unknown key "vehicle"; expected name, plume, field, vehicles'
        '{"sensors": [{"name": "SMOKE", "plume": {"lat": 40, "lon": -7, "radious": 60, "peak": 100}}]}' | 'sensors[0]: SMOKE: plume: unknown key "radious"; expected lat, lon, radius, peak, background'
        '{"sensors": [{"name": "SMOKE", "plume": {"lat": 40, "lon": -7, "peak": 100}}]}'           | 'sensors[0]: SMOKE: missing "radius"'
        '{"sensors": [{"name": "SMOKE", "plume": {"lat": 40, "lon": -7, "radius": -1, "peak": 100}}]}' | 'sensors[0]: SMOKE: the radius must be a positive number of metres, got -1.0'
        '{"sensors": [{"name": "SMOKE", "plume": {"lat": 40, "lon": -7, "radius": "60", "peak": 100}}]}' | 'sensors[0]: SMOKE: "radius": expected a number, got 60'
        '{"sensors": [{"name": "SMOKE", "plume": {"lat": 40, "lon": -7, "radius": 60, "peak": 1e999}}]}' | 'sensors[0]: SMOKE: the peak must be a finite number, got Infinity'
        '{"sensors": [{"name": "TEMPERATURE", "field": {"lat": 40, "lon": -7, "base": 1, "gradient": 0, "bearing": 0}}]}' | 'sensors[0]: TEMPERATURE: a sensor name must be 1 to 10 printable ASCII characters'
        '{"sensors": [{"name": "SMOKE"}]}'                                                         | 'sensors[0]: SMOKE: expected either "plume" or "field"'
        '{"sensors": [{"plume": {}}]}'                                                             | 'sensors[0]: expected a "name" string, got null'
        '{"sensors": {"name": "SMOKE"}}'                                                           | 'sensors: expected a list'
        '{"sensors": [{"name": "GAS", "field": {"lat": 40, "lon": -7, "base": 1, "gradient": 0, "bearing": 0}, "vehicles": [1, 3]}]}' | 'sensors[0]: GAS: no vehicle with system id 3 in the fleet (1..2)'
        '{"cameras": [1, "2"]}'                                                                   | 'cameras: expected a list of system ids or "all", got 2 in [1, 2]'
        '{"cameras": [7]}'                                                                        | 'cameras: no vehicle with system id 7 in the fleet (1..2)'
        '{"sensors": [}'                                                                          | 'not JSON: '
    }

    def "a missing --config file is a usage error naming it"() {
        when:
        def r = dolphin('sim', '--config', 'no/such.json', '--duration', '0')

        then:
        r.code == 2
        r.err.contains('--config no/such.json: no such file')
    }
}
