package dolphin.sitl

import dolphin.core.Position
import java.nio.file.Files
import java.nio.file.Path

/**
 * One ArduPilot SITL process (arducopter, arduplane, ardurover or ardusub, run directly, without
 * sim_vehicle.py or MAVProxy), started the way ArduPilot's docs run the binary: in its own working directory (its
 * eeprom.bin and logs go there), with an instance number (-I i: TCP ports 5760 + 10 i and up, so
 * instances never clash), a system id (--sysid N, which sets MAV_SYSID on current ArduPilot and
 * SYSID_THISMAV on older releases), a home, the vehicle's default parameter file, and SERIAL0 sending
 * UDP to our ground station's udpin port. Its output goes to sitl.log in the working directory;
 * failures quote its last lines.
 */
class SitlVehicle implements AutoCloseable {

    final String binary
    final String model
    final int sysid
    final int instance
    final Position home
    final Path dir
    private final Process process

    /**
     * @param defaults the parameter files, comma-separated (ArduPilot's Tools/autotest/default_params/copter.parm,
     *        say, or rover.parm,motorboat.parm), or null to run on the binary's built-in defaults
     * @param params parameter lines ("SCR_ENABLE 1") read after the defaults, from a file of its own
     *        (SITL's --defaults takes a comma-separated list)
     * @param scripts Lua scripts put in the working directory's scripts/ folder, where ArduPilot loads them
     */
    SitlVehicle(String binary, String model, int sysid, int instance, Position home, String defaults, double speedup, int gcsPort,
                List<String> params, List<Path> scripts) {
        this.binary = binary
        this.model = model
        this.sysid = sysid
        this.instance = instance
        this.home = home
        this.dir = Files.createTempDirectory("sitl-${model}-${sysid}-")
        List<String> cmd = [binary, '--model', model, '-I', "${instance}", '--sysid', "${sysid}",
                            '--home', String.format(Locale.ROOT, '%.7f,%.7f,%.2f,0', home.latitudeDegrees(), home.longitudeDegrees(), home.hae()),
                            '--speedup', String.valueOf(speedup), '--serial0', "udpclient:127.0.0.1:${gcsPort}"]*.toString()
        if (!scripts.isEmpty()) {
            Path folder = Files.createDirectories(dir.resolve('scripts'))
            scripts.each { Files.copy(it, folder.resolve(it.fileName)) }
        }
        List<String> parameterFiles = defaults ? [defaults] : []
        if (!params.isEmpty()) {
            parameterFiles << Files.write(dir.resolve('extra.parm'), params).toAbsolutePath().toString()
        }
        if (parameterFiles) {
            cmd += ['--defaults', parameterFiles.join(',')]
        }
        process = new ProcessBuilder(cmd).directory(dir.toFile()).redirectErrorStream(true)
                .redirectOutput(dir.resolve('sitl.log').toFile()).start()
    }

    boolean isAlive() { process.alive }

    /** The last lines of the process's output, for failure messages. */
    String logTail(int lines = 20) {
        def log = dir.resolve('sitl.log')
        Files.exists(log) ? log.readLines().takeRight(lines).join('\n') : '(no output)'
    }

    /**
     * Ends the process and every process it started (a wrapper script's java, say), forcibly after
     * 5 s, and deletes the working directory (SITL's dataflash logs grow by megabytes a minute).
     */
    @Override
    void close() {
        SitlProcesses.end(process)
        dir.toFile().deleteDir()
    }

    @Override
    String toString() { "${new File(binary).name} --sysid ${sysid} -I ${instance} (output in ${dir}/sitl.log)" }
}
