package dolphin.sitl

import java.util.concurrent.TimeUnit

/** Ends a SITL process and every process it started (a wrapper script's java, say), forcibly after 5 s. */
class SitlProcesses {

    static void end(Process process) {
        List<ProcessHandle> tree = process.descendants().toList() + [process.toHandle()]
        tree.each { it.destroy() }
        tree.each { h ->
            try {
                h.onExit().get(5, TimeUnit.SECONDS)
            } catch (java.util.concurrent.TimeoutException ignored) {
                h.destroyForcibly()
            }
        }
    }
}
