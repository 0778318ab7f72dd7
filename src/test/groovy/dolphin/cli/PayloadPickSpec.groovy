package dolphin.cli

import java.util.concurrent.CompletableFuture
import java.util.concurrent.TimeUnit
import spock.lang.Specification
import spock.lang.Timeout

/**
 * `pick { payload 'Camera' }` end to end, over UDP on loopback: the simulated fleet with a camera on
 * one vehicle, whose CAMERA_INFORMATION (asked for at discovery) makes it the one picked, and a fleet
 * file for vehicles that announce nothing.
 */
class PayloadPickSpec extends Specification {

    static final String SCRIPT = '''
camera = pick { payload 'Camera'; timeout 30 }
message "camera on ${camera}: ${payloads(camera)}"
others = pick { count 1; timeout 1 }
message "without: ${others}, ${payloads(others)}"
'''

    Map run(String script, String... options) {
        File file = File.createTempFile('payload', '.dolphin')
        file.text = script
        def out = new StringWriter()
        def err = new StringWriter()
        def code = CompletableFuture.supplyAsync {
            Main.commandLine(new PrintWriter(out), new PrintWriter(err))
                    .execute(['run', file.path, '--status', 'plain', '--speedup', '10', *options] as String[])
        }
        try {
            [code: code.get(60, TimeUnit.SECONDS), lines: out.toString().readLines().collect { it.replaceFirst(/^\[\s*[\d.]+ s\] /, '') },
             err: err.toString()]
        } finally {
            file.delete()
        }
    }

    @Timeout(70)
    def "on the simulated fleet: the vehicle whose autopilot has a camera is picked, the other is not"() {
        when:
        def r = run(SCRIPT, '--sim', '2', '--sim-camera', '2')

        then:
        r.code == 0
        r.lines.contains('camera on { 2 }: [Camera]')
        r.lines.contains('without: { 1 }, []')
    }

    @Timeout(70)
    def "with a fleet file: a vehicle that announces nothing carries what the file says, and is picked by its name"() {
        given:
        File fleet = File.createTempFile('fleet', '.json')
        fleet.text = '{"vehicles": [{"sysid": 1, "name": "watcher", "payloads": [{"name": "Camera", "model": "A7"}]}]}'

        when:
        def r = run('''
byName = pick { id 'watcher'; timeout 30 }
message "by name: ${byName}"
release byName
''' + SCRIPT, '--sim', '2', '--fleet', fleet.path)

        then:
        r.code == 0
        r.lines.contains('by name: { 1 }')
        r.lines.contains('camera on { 1 }: [Camera]')
        r.lines.contains('without: { 2 }, []')

        cleanup:
        fleet.delete()
    }
}
