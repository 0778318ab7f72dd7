package dolphin.sitl

import dolphin.core.Position
import java.nio.file.Files
import java.nio.file.Path

/**
 * One PX4 SITL process with its built-in simulator (SIH), started as PX4's own `make px4_sitl
 * sihsim_quadx` starts it, without Gazebo: the px4 binary with its ROMFS (build/.../etc, next to
 * bin/), in its own working directory (parameters and logs go there), instance i (-i: MAV_SYS_ID i + 1,
 * its ground station link listening on UDP 18570 + i), the model and home in PX4_SIM_MODEL and
 * PX4_HOME_LAT/LON/ALT, a speed factor in PX4_SIM_SPEED_FACTOR, and parameters in PX4_PARAM_NAME
 * variables, which PX4's rcS sets after its defaults (docs/px4.md, "PX4 SITL").
 */
class Px4SitlVehicle implements AutoCloseable {

    /** PX4's ground station link of instance 0 listens here; instance i on the port i above. */
    static final int GCS_PORT = 18570

    final String binary
    final String model
    final int instance
    final Path dir
    private final Process process

    /** @param params parameter values by name, set at boot */
    Px4SitlVehicle(String binary, String model, int instance, Position home, double speedup, Map<String, Object> params) {
        this.binary = binary
        this.model = model
        this.instance = instance
        this.dir = Files.createTempDirectory("px4-${model}-${instance}-")
        File etc = new File(new File(binary).parentFile.parentFile, 'etc')
        assert etc.isDirectory(): "${binary}: PX4's ROMFS is not at ${etc} (the binary must be the one in build/px4_sitl_default/bin)"
        def pb = new ProcessBuilder([binary, '-i', "${instance}", '-d', etc.absolutePath]*.toString())
                .directory(dir.toFile()).redirectErrorStream(true).redirectOutput(dir.resolve('px4.log').toFile())
        Map<String, String> env = pb.environment()
        env.PX4_SIM_MODEL = "sihsim_${model}".toString()
        env.PX4_SIMULATOR = 'sihsim'
        env.PX4_SIM_SPEED_FACTOR = String.valueOf(speedup)
        env.PX4_HOME_LAT = String.format(Locale.ROOT, '%.7f', home.latitudeDegrees())
        env.PX4_HOME_LON = String.format(Locale.ROOT, '%.7f', home.longitudeDegrees())
        env.PX4_HOME_ALT = String.format(Locale.ROOT, '%.2f', home.hae())
        params.each { name, value -> env["PX4_PARAM_${name}".toString()] = String.valueOf(value) }
        process = pb.start()
    }

    /** Its system id, MAV_SYS_ID, which PX4's rcS sets to the instance + 1. */
    int getSysid() { instance + 1 }

    String logTail(int lines = 20) {
        def log = dir.resolve('px4.log')
        Files.exists(log) ? log.readLines().takeRight(lines).join('\n') : '(no output)'
    }

    /**
     * Ends the process, forcibly after 5 s, and deletes its working directory without following its
     * links: PX4 links etc and test_data there to its build and source trees.
     */
    @Override
    void close() {
        SitlProcesses.end(process)
        Files.walk(dir).withCloseable { paths -> paths.toList() }.reverse().each { Files.delete(it) }
    }

    @Override
    String toString() { "px4 -i ${instance} ${model} (output in ${dir}/px4.log)" }
}
